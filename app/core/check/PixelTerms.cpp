#include "core/check/PixelTerms.h"
#include "core/support/Language.h"

#include "core/reference/PhongReference.h"

#include <QCoreApplication>
#include <QStringList>
#include <algorithm>
#include <cmath>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct PixelTermsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PixelTerms)
};

namespace {

QString vec(const glm::dvec3 &v)
{
    return QStringLiteral("(%1, %2, %3)")
        .arg(sentenceNumber(v.x, 'f', 4))
        .arg(sentenceNumber(v.y, 'f', 4))
        .arg(sentenceNumber(v.z, 'f', 4));
}

} // namespace

std::optional<PixelTerms> pixelTerms(const SceneHits &hits, const Scene &scene,
                                     ReferenceShading shading, int x, int y, PhongEquation equation)
{
    if (x < 0 || y < 0 || x >= hits.width || y >= hits.height)
        return std::nullopt;
    const ReferenceHit &hit = hits.at(x, y);
    if (hit.object < 0)
        return std::nullopt;
    const CameraSpaceHit at = cameraSpaceHit(hits, hit);
    const Material &material = scene.objects[std::size_t(hit.object)].material;
    PixelTerms out;
    out.shading = shading;
    out.equation = equation;
    out.x = x;
    out.y = y;
    out.object = hit.object;
    out.positionCamera = at.position;
    out.positionWorld =
        glm::dvec3(glm::inverse(scene.camera.viewMatrix()) * glm::dvec4(at.position, 1.0));
    out.N = at.normal;
    out.V = glm::normalize(-at.position);
    if (shading == ReferenceShading::Normals) {
        out.intensity = normalViewColor(out.N);
        return out;
    }
    out.ambient = scene.ambient * material.ka;
    out.intensity = out.ambient;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight &light = scene.lights[i];
        if (!light.enabled)
            continue;
        const CameraSpaceLight cam = toCameraSpace(light, scene.camera.viewMatrix());
        LightTerms t;
        t.light = int(i);
        t.positionCamera = cam.position;
        const glm::dvec3 toLight = cam.position - at.position;
        t.distance = glm::length(toLight);
        t.L = toLight / t.distance;
        t.R = glm::reflect(-t.L, out.N);
        t.NdotL = glm::dot(out.N, t.L);
        t.RdotV = glm::dot(t.R, out.V);
        const glm::dvec3 sum = t.L + out.V;
        t.H = glm::length(sum) > 0.0 ? glm::normalize(sum)
                                     : glm::dvec3(0.0); // none for a light straight behind
        t.NdotH = glm::dot(out.N, t.H);
        t.attenuation = attenuationFactor(cam.attenuation, t.distance);
        const bool slide = shading == ReferenceShading::Phong && equation == PhongEquation::Slide;
        if (t.NdotL > 0.0 || slide) {
            const double factor = shading == ReferenceShading::BlinnPhong
                ? std::pow(std::max(0.0, t.NdotH), kBlinnExponentFactor * material.shininess)
                : std::pow(std::max(0.0, t.RdotV), material.shininess);
            t.diffuse = t.attenuation * cam.diffuse * material.kd * std::max(0.0, t.NdotL);
            t.specular = t.attenuation * cam.specular * material.ks * factor;
        }
        out.intensity += t.diffuse + t.specular;
        out.lights.push_back(t);
    }
    return out;
}

QString PixelTerms::toText() const
{
    QStringList lines;
    const QString equation = shading == ReferenceShading::BlinnPhong ? QStringLiteral("Blinn-Phong")
        : shading == ReferenceShading::Normals ? PixelTermsWords::tr("normals view")
        : this->equation == PhongEquation::Slide
        ? PixelTermsWords::tr("Phong, the slide's equation (a highlight even where N·L <= 0)")
        : QStringLiteral("Phong");
    lines << PixelTermsWords::tr("pixel (%1, %2), object %3, %4")
                 .arg(x)
                 .arg(y)
                 .arg(object)
                 .arg(equation);
    lines << QStringLiteral("P world  %1").arg(vec(positionWorld));
    lines << QStringLiteral("P camera %1").arg(vec(positionCamera));
    lines << QStringLiteral("N        %1").arg(vec(N));
    lines << QStringLiteral("V        %1").arg(vec(V));
    lines << QStringLiteral("Ia·ka    %1").arg(vec(ambient));
    for (const LightTerms &t : lights) {
        lines
            << PixelTermsWords::tr("light %1").arg(t.light + 1); // as the Lights dock numbers them
        lines << QStringLiteral("  L      %1").arg(vec(t.L));
        lines << QStringLiteral("  R      %1").arg(vec(t.R));
        lines << QStringLiteral("  d      %1").arg(sentenceNumber(t.distance, 'f', 4));
        lines << QStringLiteral("  f_att  %1").arg(sentenceNumber(t.attenuation, 'f', 4));
        lines << QStringLiteral("  N·L    %1").arg(sentenceNumber(t.NdotL, 'f', 4));
        if (shading == ReferenceShading::BlinnPhong) {
            lines << QStringLiteral("  H      %1").arg(vec(t.H));
            lines << QStringLiteral("  N·H    %1").arg(sentenceNumber(t.NdotH, 'f', 4));
        } else {
            lines << QStringLiteral("  R·V    %1").arg(sentenceNumber(t.RdotV, 'f', 4));
        }
        lines << QStringLiteral("  diffuse  %1").arg(vec(t.diffuse));
        lines << QStringLiteral("  specular %1").arg(vec(t.specular));
    }
    lines << PixelTermsWords::tr("I exact  %1 -> 8-bit (%2, %3, %4)")
                 .arg(vec(intensity))
                 .arg(encodeChannel(intensity.r))
                 .arg(encodeChannel(intensity.g))
                 .arg(encodeChannel(intensity.b));
    return lines.join(QLatin1Char('\n'));
}

} // namespace phonglab
