#include "PageMatrices.h"

#include "DrawBindings.h"

#include <QCoreApplication>

#include <glm/matrix.hpp>

#include <cmath>
#include <set>
#include <tuple>

namespace phonglab {

struct PageMatricesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageMatrices)
};

namespace {

constexpr double kSameMatrix = 1e-3; // largest element difference, after scaling

// Whether a equals b up to a positive factor (a normal matrix scaled by
// any factor gives the same normalised normals).
bool sameUpToScale(const glm::dmat3 &a, const glm::dmat3 &b)
{
    double normA = 0, normB = 0, dotAB = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
            normA += a[c][r] * a[c][r];
            normB += b[c][r] * b[c][r];
            dotAB += a[c][r] * b[c][r];
        }
    if (normA < 1e-24 || normB < 1e-24 || dotAB <= 0)
        return false;
    const double scale = std::sqrt(normA / normB);
    double largest = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            largest = std::max(largest, std::abs(a[c][r] - scale * b[c][r]));
    return largest <= kSameMatrix * std::sqrt(normA);
}

bool sameMatrix(const glm::dmat4 &a, const glm::dmat4 &b)
{
    double scale = 0, largest = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            scale = std::max(scale, std::abs(a[c][r]));
            largest = std::max(largest, std::abs(a[c][r] - b[c][r]));
        }
    return largest <= kSameMatrix * std::max(1.0, scale);
}

std::optional<glm::dmat4> matrixOf(const CapturedOp &draw, const ProgramBindings &bindings,
                                   BindingMeaning meaning, QString *name = nullptr)
{
    const CapturedUniform *u = uniformMeaning(draw, bindings, meaning);
    if (!u)
        return std::nullopt;
    if (name)
        *name = u->name;
    return uniformMatrix(*u);
}

// The model-view the draw used: sent, or made of the model and view sent.
std::optional<glm::dmat4> modelViewOf(const CapturedOp &draw, const ProgramBindings &bindings)
{
    if (const auto mv = matrixOf(draw, bindings, BindingMeaning::ModelView))
        return mv;
    const auto model = matrixOf(draw, bindings, BindingMeaning::Model);
    const auto view = matrixOf(draw, bindings, BindingMeaning::View);
    if (model && view)
        return *view * *model;
    return std::nullopt;
}

JavaScriptFinding normalMatrixFinding(const CapturedUniform &sent, const glm::dmat3 &normal,
                                      const glm::dmat3 &of, bool ofModel)
{
    const glm::dmat3 expected = glm::transpose(glm::inverse(of));
    JavaScriptFinding f{{}, sent.name, true, {}, callSiteText(sent.setAt)};
    const QString what = ofModel ? PageMatricesWords::tr("the model matrix")
                                 : PageMatricesWords::tr("the model-view");
    if (sameUpToScale(normal, expected)) {
        f.key = QStringLiteral("normal-matrix-right");
        f.mistake = false;
        f.message = PageMatricesWords::tr("%1 is the inverse transpose of %2").arg(sent.name, what);
    } else if (sameUpToScale(normal, glm::transpose(of))) {
        f.key = QStringLiteral("normal-matrix-transpose");
        f.message = PageMatricesWords::tr("%1 is the transpose of %2, not its inverse transpose: "
                                          "where it rotates, the normals turn the other way")
                        .arg(sent.name, what);
    } else if (sameUpToScale(normal, glm::inverse(of))) {
        f.key = QStringLiteral("normal-matrix-inverse");
        f.message = PageMatricesWords::tr("%1 is the inverse of %2, not its inverse transpose")
                        .arg(sent.name, what);
    } else if (sameUpToScale(normal, of)) {
        f.key = QStringLiteral("normal-matrix-model-view");
        f.message = PageMatricesWords::tr("%1 is %2 itself, not its inverse transpose: under a "
                                          "scaling that is not uniform the normals tilt")
                        .arg(sent.name, what);
    } else {
        f.key = QStringLiteral("normal-matrix-other");
        f.message = PageMatricesWords::tr("%1 is not the inverse transpose of %2 sent")
                        .arg(sent.name, what);
    }
    return f;
}

void checkNormalMatrix(const CapturedOp &draw, const ProgramBindings &bindings,
                       std::vector<JavaScriptFinding> *out)
{
    for (const auto &[meaning, ofModel] : {std::pair{BindingMeaning::NormalMatrix, false},
                                           std::pair{BindingMeaning::ModelNormalMatrix, true}}) {
        const CapturedUniform *sent = uniformMeaning(draw, bindings, meaning);
        const std::optional<glm::dmat4> normal = sent ? uniformMatrix(*sent) : std::nullopt;
        const std::optional<glm::dmat4> of =
            ofModel ? matrixOf(draw, bindings, BindingMeaning::Model) : modelViewOf(draw, bindings);
        if (!normal || !of)
            continue;
        JavaScriptFinding f =
            normalMatrixFinding(*sent, glm::dmat3(*normal), glm::dmat3(*of), ofModel);
        // A camera normal matrix that is the model's alone: the view forgotten.
        if (!ofModel && f.key == QLatin1String("normal-matrix-other"))
            if (const auto model = matrixOf(draw, bindings, BindingMeaning::Model); model
                && sameUpToScale(glm::dmat3(*normal),
                                 glm::transpose(glm::inverse(glm::dmat3(*model))))) {
                f.key = QStringLiteral("normal-matrix-model");
                f.message = PageMatricesWords::tr("%1 is the inverse transpose of the model "
                                                  "matrix alone: the view is left out, so the "
                                                  "normals are in world coordinates and the rest "
                                                  "in camera coordinates")
                                .arg(sent->name);
            }
        out->push_back(f);
    }
}

void checkProducts(const CapturedOp &draw, const ProgramBindings &bindings,
                   std::vector<JavaScriptFinding> *out)
{
    QString mvName, mvpName;
    const auto mv = matrixOf(draw, bindings, BindingMeaning::ModelView, &mvName);
    const auto model = matrixOf(draw, bindings, BindingMeaning::Model);
    const auto view = matrixOf(draw, bindings, BindingMeaning::View);
    const CapturedUniform *mvUniform = uniformMeaning(draw, bindings, BindingMeaning::ModelView);
    if (mv && model && view && !sameMatrix(*mv, *view * *model))
        out->push_back({QStringLiteral("matrices-disagree"), mvName, true,
                        PageMatricesWords::tr("%1 is not the view matrix times the model matrix "
                                              "the page sends beside it")
                            .arg(mvName),
                        callSiteText(mvUniform->setAt)});
    const auto mvp = matrixOf(draw, bindings, BindingMeaning::ModelViewProjection, &mvpName);
    const auto projection = matrixOf(draw, bindings, BindingMeaning::Projection);
    const auto modelView = modelViewOf(draw, bindings);
    if (mvp && projection && modelView && !sameMatrix(*mvp, *projection * *modelView))
        out->push_back(
            {QStringLiteral("matrices-disagree"), mvpName, true,
             PageMatricesWords::tr("%1 is not the projection times the model-view the page "
                                   "sends beside it")
                 .arg(mvpName),
             callSiteText(
                 uniformMeaning(draw, bindings, BindingMeaning::ModelViewProjection)->setAt)});
}

void checkLightW(const CapturedOp &draw, const ProgramBindings &bindings,
                 std::vector<JavaScriptFinding> *out)
{
    for (BindingMeaning meaning :
         {BindingMeaning::LightPosition, BindingMeaning::LightPositionCamera})
        for (const VariableBinding *b : bindings.bound(meaning)) {
            const CapturedUniform *u = draw.uniform(b->variable.name);
            if (!u || u->glType != 0x8B52) // FLOAT_VEC4
                continue;
            for (const std::vector<double> &v : u->values)
                if (v.size() == 4 && v[3] == 0.0) {
                    // A direction by design (Angel's examples light from
                    // vec4(1, 1, 1, 0)) where the shader treats it so: said,
                    // not counted against the page.
                    out->push_back({QStringLiteral("light-w-zero"), u->name, false,
                                    PageMatricesWords::tr("%1 is sent with w = 0: a direction, "
                                                          "not a place; right only where the "
                                                          "shader lights from a direction")
                                        .arg(u->name),
                                    callSiteText(u->setAt)});
                    break;
                }
        }
}

// A product the page sends beside its factors (ambientProduct beside the
// light's ambient and the material's ka): the product must be theirs.
void checkProductsAgainstFactors(const CapturedOp &draw, const ProgramBindings &bindings,
                                 std::vector<JavaScriptFinding> *out)
{
    const std::tuple<BindingMeaning, BindingMeaning, BindingMeaning> products[] = {
        {BindingMeaning::AmbientProduct, BindingMeaning::Ambient, BindingMeaning::Ka},
        {BindingMeaning::DiffuseProduct, BindingMeaning::LightDiffuse, BindingMeaning::Kd},
        {BindingMeaning::SpecularProduct, BindingMeaning::LightSpecular, BindingMeaning::Ks}};
    for (const auto &[product, light, material] : products) {
        const CapturedUniform *p = uniformMeaning(draw, bindings, product);
        const CapturedUniform *l = uniformMeaning(draw, bindings, light);
        const CapturedUniform *m = uniformMeaning(draw, bindings, material);
        if (!p || !l || !m || p->values.empty() || l->values.empty() || m->values.empty())
            continue;
        const std::vector<double> &pv = p->values.front(), &lv = l->values.front(),
                                  &mv = m->values.front();
        bool same = true;
        for (std::size_t c = 0; c < 3 && c < pv.size() && c < lv.size() && c < mv.size(); ++c)
            same = same && std::abs(pv[c] - lv[c] * mv[c]) <= 1e-4 * std::max(1.0, std::abs(pv[c]));
        if (!same)
            out->push_back(
                {QStringLiteral("product-not-of-its-factors"), p->name, true,
                 PageMatricesWords::tr("%1 is not %2 · %3, which the page sends beside it")
                     .arg(p->name, l->name, m->name),
                 callSiteText(p->setAt)});
    }
}

} // namespace

std::vector<JavaScriptFinding> checkPageMatrices(const PageCapture &capture,
                                                 const ExplicitBindings &explicitBindings)
{
    std::vector<JavaScriptFinding> out;
    std::set<int> seen; // one program's findings once
    for (const CapturedOp *draw : capture.draws()) {
        if (!seen.insert(draw->program).second)
            continue;
        const ProgramBindings bindings = drawBindings(*draw, explicitBindings);
        checkNormalMatrix(*draw, bindings, &out);
        checkProducts(*draw, bindings, &out);
        checkLightW(*draw, bindings, &out);
        checkProductsAgainstFactors(*draw, bindings, &out);
    }
    return out;
}

} // namespace phonglab
