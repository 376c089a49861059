// What a script reads from `phonglab`, and a newcomer's slips:
// one wording for what is not known, with the nearest suggested; exit 2 for
// a slip; a path named once; stderr silent unless something is wrong; what
// `check` says about the file it checks.
#include "PhonglabProcess.h"
#include "ShaderMutations.h"
#include "TestPaths.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

QString checkScene()
{
    return sourcePath(QStringLiteral("assets/scenes/check.json"));
}

QString smallScene()
{
    return testDataPath(QStringLiteral("scenes/gl_sphere_one_light.json"));
}

QJsonObject jsonOf(const ProcessRun &r)
{
    return QJsonDocument::fromJson(r.out).object();
}

} // namespace

class TestCliContract : public QObject
{
    Q_OBJECT

private slots:
    void helpSaysWhatTheManPageSays();
    void unknownWordsAreUsageErrors_data();
    void unknownWordsAreUsageErrors();
    void aValuedFlagGivenTwiceIsRefused();
    void anotherImageFormatIsRefused();
    void aPathIsNamedOnce();
    void stderrIsQuietWithoutXdgRuntimeDir();
    void checkJsonLocatesItsErrors();
    void checkSaysTheScenesWarnings();
    void whatCannotShowIgnoresTheTolerance();
    void flatAndFacetedAreNamedPerFace_data();
    void flatAndFacetedAreNamedPerFace();
    void unknownBuiltinNamesFileAndField();
    void creaseWithTheFilesNormalsIsSaid();
    void sceneFormatExamplesRunAsWritten();
    void missingSceneShaderFailsTheCommandLine();
    void missingSemicolonIsPointedWhereItBelongs();
    void unknownEglPlatformIsNamed();
    void aMeshWhereASceneBelongsIsSaid();

private:
    QString write(const QString &name, const QByteArray &contents);
    QTemporaryDir m_dir;
};

QString TestCliContract::write(const QString &name, const QByteArray &contents)
{
    const QString path = m_dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(contents) != contents.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

void TestCliContract::helpSaysWhatTheManPageSays()
{
    const QString top = QString::fromUtf8(runPhonglab({"--help"}).out);
    QVERIFY2(top.contains(QStringLiteral("phonglab --version")), qPrintable(top));
    const QString check = QString::fromUtf8(runPhonglab({"check", "--help"}).out);
    for (const char *said :
         {"tolerance, worst", "notes, warnings", "bright green 1/255", "yellow 4/255", "per-face"})
        QVERIFY2(check.contains(QString::fromUtf8(said)), said);
}

void TestCliContract::unknownWordsAreUsageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected"); // the whole first line after "phonglab: error: "
    QTest::addColumn<QString>("synopsis"); // a piece of the synopsis printed after it
    const QString scene = smallScene();
    const QString top = QStringLiteral("usage: phonglab [SCENE.json");
    QTest::newRow("command, near")
        << QStringList{"meshinfo", "x.obj"}
        << "unknown command 'meshinfo' (did you mean 'mesh-info'?)" << top;
    QTest::newRow("command, far") << QStringList{"frobnicate"} << "unknown command 'frobnicate'"
                                  << top;
    QTest::newRow("missing file") << QStringList{"nosuch.json"}
                                  << "nosuch.json: no such file, and not a command" << top;
    QTest::newRow("top-level option")
        << QStringList{"--frobnicate"} << "unknown option '--frobnicate'" << top;
    QTest::newRow("top-level option, near") << QStringList{"--verison"}
                                            << "unknown option '--verison' (did you mean "
                                               "'--version'?)"
                                            << top;
    QTest::newRow("window option")
        << QStringList{scene, "--fragmnet", "x.frag"}
        << "unknown option '--fragmnet' (did you mean '--fragment'?)" << top;
    QTest::newRow("render") << QStringList{"render", scene, "--szie", "100x100", "-o", "x.png"}
                            << "unknown option '--szie' (did you mean '--size'?)"
                            << "usage: phonglab render";
    QTest::newRow("check") << QStringList{"check", scene, "--tolerence", "3"}
                           << "unknown option '--tolerence' (did you mean '--tolerance'?)"
                           << "usage: phonglab check";
    QTest::newRow("mesh-info") << QStringList{"mesh-info", "x.obj", "--jsn"}
                               << "unknown option '--jsn' (did you mean '--json'?)"
                               << "usage: phonglab mesh-info";
    QTest::newRow("bench") << QStringList{"bench", "--quik"}
                           << "unknown option '--quik' (did you mean '--quick'?)"
                           << "usage: phonglab bench";
    QTest::newRow("grade") << QStringList{"grade", "folder", "--scne", "x.json"}
                           << "unknown option '--scne' (did you mean '--scene'?)"
                           << "usage: phonglab grade";
}

void TestCliContract::unknownWordsAreUsageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    QFETCH(QString, synopsis);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY")); // the window's slips too are told without one
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    const ProcessRun r = runPhonglabIn(env, args);
    QCOMPARE(r.exitCode, 2);
    const QStringList lines = r.err.split(QLatin1Char('\n'));
    QCOMPARE(lines.value(0), QStringLiteral("phonglab: error: ") + expected);
    QVERIFY2(lines.value(1).startsWith(synopsis), qPrintable(r.err));
}

void TestCliContract::aValuedFlagGivenTwiceIsRefused()
{
    const QString out = m_dir.filePath(QStringLiteral("twice.png"));
    const ProcessRun r =
        runPhonglab({"render", smallScene(), "-o", out, "--size", "10x10", "--size", "20x20"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.startsWith(QStringLiteral("phonglab: error: --size given more than once "
                                             "('10x10', then '20x20')")),
             qPrintable(r.err));
    QVERIFY(!QFile::exists(out));
    // --bind is made to repeat.
    const ProcessRun bound = runPhonglab({"render", smallScene(), "-o", out, "--size", "16x16",
                                          "--bind", "Ia=Ia", "--bind", "ka=ka"});
    QVERIFY2(bound.exitCode == 0, qPrintable(bound.err));
}

void TestCliContract::anotherImageFormatIsRefused()
{
    const QString jpg = m_dir.filePath(QStringLiteral("out.jpg"));
    const ProcessRun r = runPhonglab({"render", smallScene(), "-o", jpg, "--size", "16x16"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QStringLiteral("PhongLab writes PNG images only")), qPrintable(r.err));
    QVERIFY(!QFile::exists(jpg));
    const ProcessRun diff = runPhonglab({"check", smallScene(), "--size", "16x16", "--diff", jpg});
    QCOMPARE(diff.exitCode, 2);
    QVERIFY(!QFile::exists(jpg));
    // No suffix, or one no image format uses, stays a PNG.
    const QString plain = m_dir.filePath(QStringLiteral("out"));
    QCOMPARE(runPhonglab({"render", smallScene(), "-o", plain, "--size", "16x16"}).exitCode, 0);
    QFile written(plain);
    QVERIFY(written.open(QIODevice::ReadOnly));
    QCOMPARE(written.read(4), QByteArray("\x89PNG"));
}

void TestCliContract::aPathIsNamedOnce()
{
    const QString missing = m_dir.filePath(QStringLiteral("nosuch.json"));
    for (const char *command : {"render", "check"}) {
        QStringList args{QString::fromLatin1(command), missing};
        if (args.front() == QLatin1String("render"))
            args << "-o" << m_dir.filePath("x.png");
        const ProcessRun r = runPhonglab(args);
        QVERIFY2(r.err.contains(
                     QStringLiteral("phonglab: error: %1: cannot read scene file").arg(missing)),
                 qPrintable(r.err));
        QCOMPARE(r.err.count(missing), 1);
    }
    const ProcessRun diff =
        runPhonglab({"check", smallScene(), "--size", "64x48", "--diff", "/nonexistent-dir/d.png"});
    QCOMPARE(diff.exitCode, 1);
    QCOMPARE(diff.err.count(QStringLiteral("/nonexistent-dir/d.png")), 1);
}

void TestCliContract::stderrIsQuietWithoutXdgRuntimeDir()
{
    // A grader's script, a container, ssh: no XDG_RUNTIME_DIR. Nothing went
    // wrong, so nothing is said.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("XDG_RUNTIME_DIR"));
    env.insert(QStringLiteral("TMPDIR"), m_dir.path());
    const QString out = m_dir.filePath(QStringLiteral("quiet.png"));
    const ProcessRun render =
        runPhonglabIn(env, {"render", smallScene(), "-o", out, "--size", "32x32"});
    QCOMPARE(render.exitCode, 0);
    QCOMPARE(render.err, QString());
    const ProcessRun check = runPhonglabIn(env, {"check", smallScene(), "--size", "64x48"});
    QCOMPARE(check.exitCode, 0);
    QCOMPARE(check.err, QString());
}

void TestCliContract::checkJsonLocatesItsErrors()
{
    const QString broken =
        write(QStringLiteral("broken.json"), "{\n  \"mesh\": \"builtin:sphere\",\n  \"x\": }\n");
    const QJsonObject syntax = jsonOf(runPhonglab({"check", broken, "--json"}));
    const QJsonObject error = syntax.value("errors").toArray().at(0).toObject();
    QCOMPARE(error.value("file").toString(), broken);
    QCOMPARE(error.value("line").toInt(), 3);
    const int column = error.value("column").toInt();
    QVERIFY2(column >= 8, qPrintable(QString::number(column))); // at or just past the '}'
    QVERIFY2(
        error.value("message").toString().contains(QStringLiteral("line 3, column %1").arg(column)),
        qPrintable(error.value("message").toString()));
    QVERIFY(syntax.value("max_error").isNull() && syntax.value("bad_fraction").isNull());

    const QString vertex = m_dir.filePath(QStringLiteral("missing.vert"));
    const QJsonObject unread =
        jsonOf(runPhonglab({"check", smallScene(), "--vertex", vertex, "--json"}));
    const QJsonObject missing = unread.value("errors").toArray().at(0).toObject();
    QCOMPARE(missing.value("file").toString(), vertex);
    QVERIFY2(!missing.value("message").toString().contains(vertex),
             qPrintable(missing.value("message").toString()));
}

void TestCliContract::checkSaysTheScenesWarnings()
{
    QFile original(smallScene());
    QVERIFY(original.open(QIODevice::ReadOnly));
    QJsonObject scene = QJsonDocument::fromJson(original.readAll()).object();
    scene.insert(QStringLiteral("shadnig"), QStringLiteral("flat"));
    const QString path =
        write(QStringLiteral("typo.json"), QJsonDocument(scene).toJson(QJsonDocument::Compact));
    const ProcessRun r = runPhonglab({"check", path, "--size", "64x48", "--json"});
    const QJsonArray warnings = jsonOf(r).value("warnings").toArray();
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(warnings.at(0).toString().startsWith(QStringLiteral("shadnig: unknown key")),
             qPrintable(warnings.at(0).toString()));
    QVERIFY2(
        r.err.contains(QStringLiteral("phonglab: warning: %1: shadnig: unknown key").arg(path)),
        qPrintable(r.err));
    // A clean scene has the key too, empty.
    const ProcessRun clean = runPhonglab({"check", smallScene(), "--size", "64x48", "--json"});
    QVERIFY(jsonOf(clean).value("warnings").isArray());
    QVERIFY(jsonOf(clean).value("warnings").toArray().isEmpty());
}

void TestCliContract::whatCannotShowIgnoresTheTolerance()
{
    // reflect(L, N) is far off here; a tolerance that lets it pass must
    // not call it undetectable.
    const QString fragment = write(QStringLiteral("reflect.frag"),
                                   withMistake(ShaderMistake::ReflectIncident).fragment.code);
    const auto undetectable = [&](const QString &tolerance) {
        const QJsonObject o =
            jsonOf(runPhonglab({"check", checkScene(), "--size", "160x120", "--fragment", fragment,
                                "--tolerance", tolerance, "--json"}));
        return std::pair{o.value("verdict").toString(), o.value("undetectable").toArray()};
    };
    const auto [strictVerdict, strict] = undetectable(QStringLiteral("2"));
    const auto [looseVerdict, loose] = undetectable(QStringLiteral("250"));
    QCOMPARE(strictVerdict, QStringLiteral("fail"));
    QCOMPARE(looseVerdict, QStringLiteral("pass"));
    QCOMPARE(loose, strict);
    QVERIFY(!loose.contains(QStringLiteral("reflect-incident")));
}

void TestCliContract::flatAndFacetedAreNamedPerFace_data()
{
    QTest::addColumn<QString>("method");
    QTest::newRow("flat") << QStringLiteral("flat");
    QTest::newRow("faceted") << QStringLiteral("faceted");
}

void TestCliContract::flatAndFacetedAreNamedPerFace()
{
    QFETCH(QString, method);
    const QJsonObject o = jsonOf(
        runPhonglab({"check", checkScene(), "--size", "320x240", "--shading", method, "--json"}));
    QCOMPARE(o.value("verdict").toString(), QStringLiteral("fail"));
    const QJsonObject top = o.value("diagnosis").toArray().at(0).toObject();
    QCOMPARE(top.value("key").toString(), QStringLiteral("per-face"));
    QVERIFY2(top.value("confidence").toDouble() > 0.99,
             qPrintable(QString::number(top.value("confidence").toDouble())));
    QVERIFY2(top.value("form").toString().contains(method),
             qPrintable(top.value("form").toString()));
}

void TestCliContract::unknownBuiltinNamesFileAndField()
{
    const QString path = write(QStringLiteral("cub.json"),
                               R"({"objects": [{"mesh": "builtin:sphere"},
                                               {"mesh": "builtin:cub"}]})");
    const ProcessRun r = runPhonglab({"render", path, "-o", m_dir.filePath("cub.png")});
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.err.trimmed(),
             QStringLiteral("phonglab: error: %1: objects[1].mesh: unknown builtin mesh "
                            "'builtin:cub' (did you mean 'builtin:cube'?); known: "
                            "builtin:sphere, builtin:torus, builtin:cube")
                 .arg(path));
}

void TestCliContract::creaseWithTheFilesNormalsIsSaid()
{
    const QString tree = sourcePath(QStringLiteral("assets/meshes/tree.obj"));
    const ProcessRun r = runPhonglab({"mesh-info", tree, "--crease", "30", "--json"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject o = jsonOf(r);
    QCOMPARE(o.value("normal_method").toString(), QStringLiteral("file"));
    QVERIFY(o.value("crease_deg").isNull());
    QVERIFY2(r.err.contains(QStringLiteral("--crease 30 is not used")), qPrintable(r.err));
    // Computed normals take it.
    const ProcessRun computed =
        runPhonglab({"mesh-info", tree, "--normals", "angle", "--crease", "30", "--json"});
    QCOMPARE(jsonOf(computed).value("crease_deg").toDouble(), 30.0);
    QCOMPARE(computed.err, QString());
}

void TestCliContract::sceneFormatExamplesRunAsWritten()
{
    // Every ```json block of docs/scene-format.md, saved where the doc says
    // (a scenes/ folder beside meshes/), renders with no error and no warning.
    QFile doc(sourcePath(QStringLiteral("docs/scene-format.md")));
    QVERIFY(doc.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(doc.readAll());
    QDir root(m_dir.path());
    QVERIFY(root.mkpath(QStringLiteral("doc/scenes")));
    QVERIFY(QFile::link(sourcePath(QStringLiteral("assets/meshes")),
                        root.filePath(QStringLiteral("doc/meshes"))));
    int examples = 0;
    const QString fence = QStringLiteral("```json\n");
    for (qsizetype at = text.indexOf(fence); at >= 0; at = text.indexOf(fence, at + 1)) {
        const qsizetype begin = at + fence.size();
        const qsizetype end = text.indexOf(QStringLiteral("```"), begin);
        QVERIFY(end > begin);
        const QString scene =
            root.filePath(QStringLiteral("doc/scenes/example-%1.json").arg(++examples));
        QFile file(scene);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(text.mid(begin, end - begin).toUtf8());
        file.close();
        const ProcessRun r =
            runPhonglab({"render", scene, "-o", scene + QStringLiteral(".png"), "--size", "64x48"});
        QVERIFY2(r.exitCode == 0 && r.err.isEmpty(),
                 qPrintable(QStringLiteral("example %1: %2").arg(examples).arg(r.err)));
    }
    QVERIFY(examples >= 2);
}

void TestCliContract::missingSceneShaderFailsTheCommandLine()
{
    // The window opens such a scene with the shipped shaders so that it can
    // be put right; a script must not get the shipped shaders' image or
    // verdict for the scene's (docs/scene-format.md, shaders).
    const QString frag = m_dir.filePath(QStringLiteral("gone.frag"));
    const QString scene = write(QStringLiteral("gone.json"),
                                QStringLiteral(R"({"mesh": "builtin:sphere",
                                   "lights": [{"position": [3, 3, 4]}],
                                   "shaders": {"fragment": "%1"}})")
                                    .arg(frag)
                                    .toUtf8());
    const ProcessRun render =
        runPhonglab({"render", scene, "-o", m_dir.filePath("gone.png"), "--size", "32x32"});
    QCOMPARE(render.exitCode, 1);
    QVERIFY2(render.err.contains(frag + QStringLiteral(": cannot read shader")),
             qPrintable(render.err));
    const ProcessRun check = runPhonglab({"check", scene, "--size", "64x48", "--json"});
    QCOMPARE(check.exitCode, 1);
    QCOMPARE(jsonOf(check).value("errors").toArray().at(0).toObject().value("file").toString(),
             frag);
}

void TestCliContract::missingSemicolonIsPointedWhereItBelongs()
{
    // The compiler finds it at "vec3" two lines on; the ';' belongs just past
    // "normalize(-positionCam)" (before the comment).
    QByteArray code = shippedPhong().fragment.code;
    const QByteArray statement = "    vec3 V = normalize(-positionCam);";
    const qsizetype at = code.indexOf(statement);
    QVERIFY(at >= 0);
    code.remove(at + statement.size() - 1, 1);
    const int line = int(code.left(at).count('\n')) + 1;
    const QString fragment = write(QStringLiteral("semicolon.frag"), code);
    const ProcessRun r = runPhonglab({"render", smallScene(), "-o", m_dir.filePath("semi.png"),
                                      "--fragment", fragment, "--size", "16x16"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.startsWith(
                 QStringLiteral("%1:%2:%3: error: ").arg(fragment).arg(line).arg(statement.size())),
             qPrintable(r.err));
}

void TestCliContract::unknownEglPlatformIsNamed()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("PHONGLAB_EGL_PLATFORM"), QStringLiteral("bogus"));
    const ProcessRun r = runPhonglabIn(
        env, {"render", smallScene(), "-o", m_dir.filePath("bogus.png"), "--size", "16x16"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral(
                 "PHONGLAB_EGL_PLATFORM=bogus names no platform (device, surfaceless)")),
             qPrintable(r.err));
}

void TestCliContract::aMeshWhereASceneBelongsIsSaid()
{
    const QString tree = sourcePath(QStringLiteral("assets/meshes/tree.obj"));
    const ProcessRun r = runPhonglab({"render", tree, "-o", m_dir.filePath("tree.png")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.startsWith(QStringLiteral("phonglab: error: %1: a mesh, not a scene: name it "
                                             "in one, {\"mesh\": \"tree.obj\"")
                                  .arg(tree)),
             qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestCliContract)
#include "tst_clicontract.moc"
