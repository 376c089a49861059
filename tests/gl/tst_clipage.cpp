// phonglab check --page / --capture and grade --pages as scripts run them:
// the real executable on the test projects of tests/data/pages, its JSON
// keys, its exit codes and the files it writes.
#include "PhonglabProcess.h"
#include "TestPaths.h"
#include "core/page/BrowserPipe.h"

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

QStringList pageArguments(const QString &project)
{
    return {QStringLiteral("--page"),    testDataPath(QStringLiteral("pages/") + project),
            QStringLiteral("--library"), testDataPath(QStringLiteral("pages")),
            QStringLiteral("--library"), sourcePath(QStringLiteral("assets/meshes"))};
}

QJsonObject jsonOf(const ProcessRun &run)
{
    return QJsonDocument::fromJson(run.out).object();
}

} // namespace

class TestCliPage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void aRightPagePasses();
    void aTransposedNormalMatrixFails();
    void aCaptureIsCheckedAgainWithoutTheBrowser();
    void theOwnScenesMistakeIsOnTheStudentsLine();
    void theCourseSceneWithThePagesProgram();
    void theScenesPageSettingsAreTaken();
    void wrongArgumentsAreUsageErrors();
    void noBrowserSaysHowToInstallOne();
    void gradeRunsEachPage();

private:
    QTemporaryDir m_dir;
    QString m_meshes; // the course's meshes: the cloud alone, as the Angel-style page draws
};

void TestCliPage::initTestCase()
{
    if (BrowserPipe::executable().isEmpty())
        QSKIP("chromium is not installed (scripts/setup.sh installs it)");
    m_meshes = m_dir.filePath(QStringLiteral("meshes"));
    QVERIFY(QDir().mkpath(m_meshes));
    QVERIFY(QFile::copy(sourcePath(QStringLiteral("assets/meshes/cloud.obj")),
                        m_meshes + QStringLiteral("/cloud.obj")));
}

void TestCliPage::aRightPagePasses()
{
    const ProcessRun run =
        runPhonglab(QStringList{QStringLiteral("check")} + pageArguments(QStringLiteral("angel"))
                    + QStringList{QStringLiteral("--meshes"), m_meshes, QStringLiteral("--json")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err + QString::fromUtf8(run.out)));
    const QJsonObject json = jsonOf(run);
    QCOMPARE(json.value("verdict").toString(), QStringLiteral("pass"));
    const QJsonObject page = json.value("page").toObject();
    for (const char *key :
         {"file", "webgl", "frame", "animated", "canvas", "milliseconds", "steps", "served",
          "refused", "errors", "console_errors", "fidelity", "javascript", "mesh_errors"})
        QVERIFY2(page.contains(QLatin1String(key)), key);
    const QJsonObject fidelity = page.value("fidelity").toObject();
    QVERIFY(fidelity.value("faithful").toBool());
    qInfo("fidelity of the Angel-style page: largest difference %d outside edges",
          fidelity.value("largest_difference").toInt());
    const QJsonArray javascript = page.value("javascript").toArray();
    QCOMPARE(javascript.size(), 2);
    QCOMPARE(javascript[0].toObject().value("key").toString(), QStringLiteral("normals-exact"));
    QCOMPARE(javascript[1].toObject().value("key").toString(),
             QStringLiteral("normal-matrix-right"));
}

void TestCliPage::aTransposedNormalMatrixFails()
{
    const ProcessRun run =
        runPhonglab(QStringList{QStringLiteral("check")} + pageArguments(QStringLiteral("angel"))
                    + QStringList{QStringLiteral("--page-step"),
                                  QStringLiteral("select #normalMatrix=transpose")});
    QCOMPARE(run.exitCode, 1);
    const QString text = QString::fromUtf8(run.out);
    QVERIFY2(text.contains(QRegularExpression(
                 QStringLiteral(R"(phong\.js:\d+: javascript: normalMatrix is the transpose)"))),
             qPrintable(text));
    QVERIFY(text.contains(QLatin1String("verdict: fail")));
}

// --page-out writes the capture and the three frames; --capture checks the
// capture again, without the browser, to the same findings.
void TestCliPage::aCaptureIsCheckedAgainWithoutTheBrowser()
{
    const QString out = m_dir.filePath(QStringLiteral("out"));
    const ProcessRun first =
        runPhonglab(QStringList{QStringLiteral("check")} + pageArguments(QStringLiteral("angel"))
                    + QStringList{QStringLiteral("--page-out"), out, QStringLiteral("--json")});
    QCOMPARE(first.exitCode, 0);
    for (const char *name : {"capture.json", "browser.png", "phonglab.png", "difference.png"})
        QVERIFY2(QFile::exists(out + QLatin1Char('/') + QLatin1String(name)), name);
    QVERIFY(QDir(out).entryList({QStringLiteral("browser-*")}, QDir::Dirs).isEmpty());
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PHONGLAB_CHROMIUM"), QString()); // no browser needed
    const ProcessRun again =
        runPhonglabIn(env,
                      {QStringLiteral("check"), QStringLiteral("--capture"),
                       out + QStringLiteral("/capture.json"), QStringLiteral("--json")});
    QVERIFY2(again.exitCode == 0, qPrintable(again.err));
    const QJsonObject a = jsonOf(first).value("page").toObject();
    const QJsonObject b = jsonOf(again).value("page").toObject();
    QCOMPARE(b.value("fidelity"), a.value("fidelity"));
    QCOMPARE(b.value("javascript"), a.value("javascript"));
    const ProcessRun broken = runPhonglab({QStringLiteral("check"), QStringLiteral("--capture"),
                                           out + QStringLiteral("/browser.png")});
    QCOMPARE(broken.exitCode, 1);
    QVERIFY2(broken.err.contains(QLatin1String("browser.png: not JSON")), qPrintable(broken.err));
}

// The student's own scene, drawn with reflect(l, n): the mistake named, on
// the line of the page handed in.
void TestCliPage::theOwnScenesMistakeIsOnTheStudentsLine()
{
    // The Angel-style project with the one mistake made in its page.
    const QString project = m_dir.filePath(QStringLiteral("angel-reflect"));
    QVERIFY(QDir().mkpath(project));
    QFile page(testDataPath(QStringLiteral("pages/angel/index.html")));
    QVERIFY(page.open(QIODevice::ReadOnly));
    QByteArray html = page.readAll();
    QVERIFY(html.contains("vec3 r = reflect(-l, n);"));
    html.replace("vec3 r = reflect(-l, n);", "vec3 r = reflect(l, n);");
    QFile mistaken(project + QStringLiteral("/index.html"));
    QVERIFY(mistaken.open(QIODevice::WriteOnly) && mistaken.write(html) == html.size());
    mistaken.close();
    QVERIFY(QFile::copy(testDataPath(QStringLiteral("pages/angel/phong.js")),
                        project + QStringLiteral("/phong.js")));
    QStringList arguments = pageArguments(QStringLiteral("angel"));
    arguments[1] = project;
    const ProcessRun run = runPhonglab(QStringList{QStringLiteral("check")} + arguments
                                       + QStringList{QStringLiteral("--json")});
    QCOMPARE(run.exitCode, 1);
    const QJsonObject own = jsonOf(run).value("page").toObject().value("own_scene").toObject();
    QCOMPARE(own.value("verdict").toString(), QStringLiteral("fail"));
    QCOMPARE(own.value("mistakes").toArray().first().toString(),
             QStringLiteral("reflect-incident"));
    const QJsonObject line = own.value("lines").toArray().first().toObject();
    QCOMPARE(line.value("file").toString(), QStringLiteral("index.html"));
    QCOMPARE(line.value("line").toInt(), 47);
    QCOMPARE(line.value("text").toString(), QStringLiteral("vec3 r = reflect(l, n);"));
}

// With a scene: the course scene checked with the program the page drew,
// on the student's own lines, and the page's findings beside.
void TestCliPage::theCourseSceneWithThePagesProgram()
{
    const ProcessRun run =
        runPhonglab(QStringList{QStringLiteral("check"),
                                sourcePath(QStringLiteral("assets/scenes/default.json"))}
                    + pageArguments(QStringLiteral("angel"))
                    + QStringList{QStringLiteral("--bind"),
                                  QStringLiteral("lightPosition=light-position-camera"),
                                  QStringLiteral("--json")});
    const QJsonObject json = jsonOf(run);
    QVERIFY2(json.contains("psnr_db") && json.contains("page"), qPrintable(run.err));
    const QString notes = QString::fromUtf8(QJsonDocument(json.value("notes").toArray()).toJson());
    QVERIFY2(
        notes.contains(QLatin1String("index.html#vertex-shader and index.html#fragment-shader")),
        qPrintable(notes));
    QVERIFY2(json.value("verdict").toString() == QLatin1String("pass"),
             qPrintable(QString::fromUtf8(run.out)));
}

// The teacher states the starter's libraries and a student's step once,
// in the scene's "page"; the command line names only the project.
void TestCliPage::theScenesPageSettingsAreTaken()
{
    QFile in(sourcePath(QStringLiteral("assets/scenes/default.json")));
    QVERIFY(in.open(QIODevice::ReadOnly));
    QJsonObject scene = QJsonDocument::fromJson(in.readAll()).object();
    for (const QString &key : {QStringLiteral("objects"), QStringLiteral("mesh")})
        if (scene.value(key).isString())
            scene.insert(
                key, sourcePath(QStringLiteral("assets/scenes/")) + scene.value(key).toString());
    QJsonArray objects = scene.value("objects").toArray();
    for (QJsonValueRef o : objects) {
        QJsonObject object = o.toObject();
        object.insert(
            "mesh", sourcePath(QStringLiteral("assets/scenes/")) + object.value("mesh").toString());
        o = object;
    }
    scene.insert("objects", objects);
    scene.insert("page",
                 QJsonObject{{"steps", QJsonArray{"select #normalMatrix=transpose"}},
                             {"libraries",
                              QJsonArray{testDataPath(QStringLiteral("pages")),
                                         sourcePath(QStringLiteral("assets/meshes"))}},
                             {"frame", 1}});
    const QString path = m_dir.filePath(QStringLiteral("course.json"));
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(scene).toJson());
    out.close();
    const ProcessRun run = runPhonglab(
        {QStringLiteral("check"), path, QStringLiteral("--page"),
         testDataPath(QStringLiteral("pages/angel")), QStringLiteral("--bind"),
         QStringLiteral("lightPosition=light-position-camera"), QStringLiteral("--json")});
    const QJsonObject page = jsonOf(run).value("page").toObject();
    QVERIFY2(page.value("frame").toInt() == 1, qPrintable(run.err + QString::fromUtf8(run.out)));
    QCOMPARE(page.value("steps").toArray().size(), 1);
    QVERIFY2(page.value("refused").toArray().isEmpty(),
             qPrintable(QJsonDocument(page.value("refused").toArray()).toJson()));
    QCOMPARE(page.value("javascript").toArray().last().toObject().value("key").toString(),
             QStringLiteral("normal-matrix-transpose"));
}

void TestCliPage::wrongArgumentsAreUsageErrors()
{
    for (const QStringList &args :
         {QStringList{QStringLiteral("check"), QStringLiteral("--page-step"),
                      QStringLiteral("click #a"),
                      sourcePath(QStringLiteral("assets/scenes/default.json"))},
          QStringList{QStringLiteral("check"), QStringLiteral("--page"), QStringLiteral("."),
                      QStringLiteral("--capture"), QStringLiteral("x.json")},
          QStringList{QStringLiteral("check"), QStringLiteral("--page"),
                      QStringLiteral("/no/such/folder")},
          QStringList{QStringLiteral("check"), QStringLiteral("--page"), QStringLiteral("."),
                      QStringLiteral("--page-frame"), QStringLiteral("0")}}) {
        const ProcessRun run = runPhonglab(args);
        QVERIFY2(run.exitCode == 2, qPrintable(args.join(' ') + ": " + run.err));
    }
}

void TestCliPage::noBrowserSaysHowToInstallOne()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PHONGLAB_CHROMIUM"), QString());
    const ProcessRun run = runPhonglabIn(
        env, QStringList{QStringLiteral("check")} + pageArguments(QStringLiteral("angel")));
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains(QLatin1String("apt install chromium")), qPrintable(run.err));
}

void TestCliPage::gradeRunsEachPage()
{
    const QString classFolder = m_dir.filePath(QStringLiteral("class"));
    for (const auto &[student, project] :
         {std::pair{"anna", "angel"}, std::pair{"ben", "webgl2fundamentals"}}) {
        const QString to = classFolder + QLatin1Char('/') + QLatin1String(student);
        QVERIFY(QDir().mkpath(to));
        const QDir from(testDataPath(QStringLiteral("pages/") + QLatin1String(project)));
        for (const QString &name : from.entryList(QDir::Files))
            QVERIFY(QFile::copy(from.filePath(name), to + QLatin1Char('/') + name));
    }
    const QString out = m_dir.filePath(QStringLiteral("grades"));
    const ProcessRun run = runPhonglab(
        {QStringLiteral("grade"), classFolder, QStringLiteral("--scene"),
         sourcePath(QStringLiteral("assets/scenes/default.json")), QStringLiteral("--out"), out,
         QStringLiteral("--pages"), QStringLiteral("--library"),
         testDataPath(QStringLiteral("pages")), QStringLiteral("--library"),
         sourcePath(QStringLiteral("assets/meshes")), QStringLiteral("--meshes"), m_meshes,
         QStringLiteral("--jobs"), QStringLiteral("2")},
        300000);
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QFile csv(out + QStringLiteral("/grades.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY(lines.first().endsWith(
        QLatin1String(",page_fidelity,page_own_scene,page_javascript,page_error")));
    QCOMPARE(lines.size(), 3);
    // anna's page draws the cloud with Blender's normals: ok; ben's draws the tree only.
    QVERIFY2(lines[1].startsWith(QLatin1String("anna,"))
                 && lines[1].endsWith(QLatin1String(",ok,")),
             qPrintable(lines[1]));
    QVERIFY2(lines[2].endsWith(QLatin1String(",normals-missing cloud.obj,")), qPrintable(lines[2]));
    for (const char *name : {"pages/anna/capture.json", "pages/ben/difference.png"})
        QVERIFY2(QFile::exists(out + QLatin1Char('/') + QLatin1String(name)), name);
    QFile report(out + QStringLiteral("/report.html"));
    QVERIFY(report.open(QIODevice::ReadOnly));
    QVERIFY(report.readAll().contains("pages/anna/browser.png"));
}

QTEST_GUILESS_MAIN(TestCliPage)
#include "tst_clipage.moc"
