// What binding by use adds to a check (prints figures; not a test).
//
//   build/tests/bench/bench_bind_by_use [--runs N] [PHONGLAB]
//
// For course code in each style (tests/data/course/) and the shipped pair:
// the median wall time of `phonglab check` on the course scene (the peer,
// in the same run), and the median time of what binding by use does in it
// (core/program/BindingsByUse over both stages' text, the variables bound
// by name first), and their ratio. The aim: at most 10 %.
#include "core/program/BindingsByUse.h"
#include "core/program/UniformAnnotations.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QStringList>

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace phonglab;

namespace {

QByteArray readFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

GlslType typeOf(const QString &spelling)
{
    static const std::vector<std::pair<QString, GlslType>> types = {
        {QStringLiteral("float"), GlslType::Float}, {QStringLiteral("int"), GlslType::Int},
        {QStringLiteral("vec3"), GlslType::Vec3},   {QStringLiteral("vec4"), GlslType::Vec4},
        {QStringLiteral("mat3"), GlslType::Mat3},   {QStringLiteral("mat4"), GlslType::Mat4}};
    for (const auto &[name, type] : types)
        if (name == spelling)
            return type;
    return GlslType::Other;
}

// The uniforms both stages declare, as the driver would list them.
std::vector<ShaderVariable> declared(const QByteArray &vertex, const QByteArray &fragment)
{
    std::vector<ShaderVariable> out;
    for (const QByteArray *code : {&vertex, &fragment})
        for (const UniformDeclaration &d : parseUniformDeclarations(QString::fromUtf8(*code)))
            if (std::none_of(out.begin(), out.end(),
                             [&](const ShaderVariable &v) { return v.name == d.name; }))
                out.push_back({d.name, typeOf(d.type), std::max(1, d.arraySize), d.isArray, false});
    return out;
}

double checkMs(const QString &exe, const QString &scene, const QString &vertex,
               const QString &fragment, const QStringList &extra)
{
    QElapsedTimer timer;
    timer.start();
    QProcess p;
    p.start(exe,
            QStringList{QStringLiteral("check"), scene, QStringLiteral("--vertex"), vertex,
                        QStringLiteral("--fragment"), fragment}
                + extra);
    p.waitForFinished(120000);
    return double(timer.nsecsElapsed()) / 1e6;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QStringList args = app.arguments().mid(1);
    int runs = 5;
    if (const qsizetype at = args.indexOf(QStringLiteral("--runs"));
        at >= 0 && at + 1 < args.size()) {
        runs = std::max(1, args[at + 1].toInt());
        args.remove(at, 2);
    }
    const QString exe = args.value(0, QStringLiteral(PHONGLAB_BINARY_DIR "/app/phonglab"));
    const QString data = QStringLiteral(PHONGLAB_SOURCE_DIR "/tests/data/course/");
    const QString scene = data + QStringLiteral("scene.json");
    struct Style {
        const char *name;
        QString vertex;
        QString fragment;
        QStringList extra;
    };
    const std::vector<Style> styles = {
        {"shipped",
         QStringLiteral(PHONGLAB_SOURCE_DIR "/shaders/phong.vert"),
         QStringLiteral(PHONGLAB_SOURCE_DIR "/shaders/phong.frag"),
         {}},
        {"angel",
         data + QStringLiteral("angel/phong.vert"),
         data + QStringLiteral("angel/phong.frag"),
         {QStringLiteral("--bind"), QStringLiteral("lightPosition=light-position-camera")}},
        {"webglfundamentals",
         data + QStringLiteral("webglfundamentals/point-light.vert"),
         data + QStringLiteral("webglfundamentals/point-light.frag"),
         {}},
        {"structs",
         data + QStringLiteral("structs/phong.vert"),
         data + QStringLiteral("structs/phong.frag"),
         {QStringLiteral("--bind"), QStringLiteral("mode=1")}},
    };
    std::printf("%-18s %12s %14s %8s\n", "style", "check ms", "by use us", "ratio");
    double worst = 0.0;
    for (const Style &s : styles) {
        const QByteArray vertex = readFile(s.vertex);
        const QByteArray fragment = readFile(s.fragment);
        if (vertex.isEmpty() || fragment.isEmpty()) {
            std::printf("%-18s (files missing: %s)\n", s.name, qPrintable(s.vertex));
            continue;
        }
        const std::vector<ShaderVariable> variables = declared(vertex, fragment);
        std::vector<double> check;
        std::vector<double> use;
        for (int r = 0; r < runs; ++r) {
            check.push_back(checkMs(exe, scene, s.vertex, s.fragment, s.extra));
            QElapsedTimer timer;
            timer.start();
            constexpr int kRepeats = 50; // one is below the clock's grain
            for (int k = 0; k < kRepeats; ++k) {
                ProgramBindings bindings = bindVariables(variables, {});
                bindByUse(bindings, vertex, fragment);
            }
            use.push_back(double(timer.nsecsElapsed()) / 1e3 / kRepeats);
        }
        const double ratio = median(use) / 1e3 / median(check);
        worst = std::max(worst, ratio);
        std::printf("%-18s %12.1f %14.1f %7.3f%%\n", s.name, median(check), median(use),
                    100.0 * ratio);
    }
    std::printf("binding by use adds at most %.3f %% to a check (aim: 10 %%), median of %d runs\n",
                100.0 * worst, runs);
    return 0;
}
