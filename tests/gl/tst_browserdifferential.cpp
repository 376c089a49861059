// PhongLab draws a WebGL shader as the student's browser drew it: probe
// shaders (tests/data/browser/probes.json) are drawn by headless Chromium
// (Debian's chromium, WebGL 1 and 2 on SwiftShader, through ANGLE) and by
// PhongLab's own build path (render/program/ProgramBuilder: the course prelude and
// core/program/BrowserRules) on this machine's driver, and their pixels are
// compared. The probes hold what GLSL leaves undefined and browsers define:
// unset locals, outputs, parameters and varyings, mediump arithmetic,
// integer loops; and two WebGL 1 loops the browser refuses, which PhongLab
// must refuse too ("refused"). A probe PhongLab cannot match says why in its "differs",
// and must then differ: the list stays true. One of them, mediump checked
// "as-written" on a driver that computes it in 16 bits, is the control
// that shows the comparison can fail.
#include "RenderCheck.h"
#include "ResultChecks.h"
#include "TestPaths.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/program/ProgramBuilder.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kSide = 8; // tests/data/browser/probe-page.html's canvas
// SwiftShader and llvmpipe round a colour to 8 bits each their own way.
constexpr int kTolerance = 1;

// Debian's chromium itself: /usr/bin/chromium is a wrapper script.
QString browserExecutable()
{
    for (const QString &path : {QStringLiteral("/usr/lib/chromium/chromium"),
                                QStandardPaths::findExecutable(QStringLiteral("chromium"))})
        if (!path.isEmpty() && QFileInfo(path).isExecutable())
            return path;
    return {};
}

QJsonArray readProbes()
{
    QFile file(testDataPath(QStringLiteral("browser/probes.json")));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).array();
}

} // namespace

class TestBrowserDifferential : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void probesDrawTheBrowsersPixels_data();
    void probesDrawTheBrowsersPixels();

private:
    QString runBrowser(const QJsonArray &probes);
    QByteArray drawHere(const QJsonObject &probe, QString *error);

    OffscreenRenderer m_offscreen;
    QJsonArray m_probes;
    std::map<QString, QString> m_browser; // probe name -> hex RGBA, or "error: ..."
};

void TestBrowserDifferential::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY_OK(m_offscreen.create());
    m_offscreen.makeCurrent();
    m_probes = readProbes();
    QVERIFY(m_probes.size() >= 20);
    if (browserExecutable().isEmpty())
        QSKIP("chromium is not installed (scripts/setup.sh installs it)");
    const QString problem = runBrowser(m_probes);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    qInfo("GL renderer here: %s; the browser: Chromium, WebGL on SwiftShader",
          qPrintable(m_offscreen.glRendererName()));
}

void TestBrowserDifferential::cleanupTestCase()
{
    m_offscreen.makeCurrent();
}

// One page draws every probe (one browser start); --dump-dom hands back the
// DOM after the load event, each probe's pixels in a <pre>.
QString TestBrowserDifferential::runBrowser(const QJsonArray &probes)
{
    QFile page(testDataPath(QStringLiteral("browser/probe-page.html")));
    if (!page.open(QIODevice::ReadOnly))
        return QStringLiteral("cannot read the probe page");
    // In a <script> element only "</" can end it early.
    const QByteArray json =
        QJsonDocument(probes).toJson(QJsonDocument::Compact).replace("</", "<\\/");
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("probes.html"));
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly)
        || out.write(page.readAll().replace("PROBES_JSON", json)) < 0)
        return QStringLiteral("cannot write the probe page");
    out.close();
    QProcess browser;
    browser.start(browserExecutable(),
                  {QStringLiteral("--headless=new"), QStringLiteral("--no-sandbox"),
                   QStringLiteral("--use-angle=swiftshader"),
                   QStringLiteral("--enable-unsafe-swiftshader"), QStringLiteral("--no-first-run"),
                   QStringLiteral("--disable-background-networking"),
                   QStringLiteral("--disable-component-update"), QStringLiteral("--disable-sync"),
                   QStringLiteral("--user-data-dir=") + dir.filePath(QStringLiteral("profile")),
                   QStringLiteral("--dump-dom"), QUrl::fromLocalFile(path).toString()});
    if (!browser.waitForFinished(120000)) {
        browser.kill();
        return QStringLiteral("chromium did not finish in 120 s");
    }
    const QString dom = QString::fromUtf8(browser.readAllStandardOutput());
    static const QRegularExpression result(
        QStringLiteral(R"re(<pre id="result-([a-z0-9-]+)">([^<]*)</pre>)re"));
    for (auto it = result.globalMatch(dom); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        m_browser[m.captured(1)] = m.captured(2);
    }
    if (m_browser.size() != std::size_t(probes.size()))
        return QStringLiteral("chromium drew %1 of %2 probes; it said: %3")
            .arg(m_browser.size())
            .arg(probes.size())
            .arg(QString::fromUtf8(browser.readAllStandardError()).right(2000));
    return {};
}

// The probe drawn by PhongLab's build path on this driver: a full-view quad,
// read back as RGBA bytes, bottom row first (as WebGL's readPixels).
QByteArray TestBrowserDifferential::drawHere(const QJsonObject &probe, QString *error)
{
    m_offscreen.makeCurrent();
    QOpenGLExtraFunctions gl(QOpenGLContext::currentContext());
    CourseOptions course;
    if (probe.value(QStringLiteral("precision")).toString() == QStringLiteral("as-written"))
        course.precision = PrecisionRule::AsWritten;
    const QString name = probe.value(QStringLiteral("name")).toString();
    const BuiltProgram built = ProgramBuilder().build(
        {name + QStringLiteral(".vert"), probe.value(QStringLiteral("vertex")).toString().toUtf8()},
        {name + QStringLiteral(".frag"),
         probe.value(QStringLiteral("fragment")).toString().toUtf8()},
        {}, {}, course);
    if (!built.ok()) {
        for (const ShaderDiagnostic &d : built.report.diagnostics)
            *error += d.message + QLatin1Char('\n');
        return {};
    }
    QOpenGLFramebufferObject target(kSide, kSide, QOpenGLFramebufferObject::NoAttachment,
                                    GL_TEXTURE_2D, GL_RGBA8);
    target.bind();
    gl.glViewport(0, 0, kSide, kSide);
    gl.glClearColor(0.2f, 0.4f, 0.6f, 1.0f); // the page's, which no probe may show
    gl.glClear(GL_COLOR_BUFFER_BIT);
    const GLuint program = built.program.id();
    gl.glUseProgram(program);
    const QJsonObject uniforms = probe.value(QStringLiteral("uniforms")).toObject();
    for (auto it = uniforms.begin(); it != uniforms.end(); ++it)
        gl.glUniform1i(gl.glGetUniformLocation(program, it.key().toUtf8().constData()),
                       it.value().toInt());
    static const float quad[] = {-1, -1, 1, -1, -1, 1, -1, 1, 1, -1, 1, 1};
    GLuint vao = 0;
    GLuint buffer = 0;
    gl.glGenVertexArrays(1, &vao);
    gl.glBindVertexArray(vao);
    gl.glGenBuffers(1, &buffer);
    gl.glBindBuffer(GL_ARRAY_BUFFER, buffer);
    gl.glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    const GLint position = gl.glGetAttribLocation(program, "a_position");
    gl.glEnableVertexAttribArray(GLuint(position));
    gl.glVertexAttribPointer(GLuint(position), 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.glDrawArrays(GL_TRIANGLES, 0, 6);
    QByteArray pixels(kSide * kSide * 4, '\0');
    gl.glReadPixels(0, 0, kSide, kSide, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    gl.glDeleteBuffers(1, &buffer);
    gl.glDeleteVertexArrays(1, &vao);
    target.release();
    if (position < 0)
        *error = QStringLiteral("the probe has no a_position");
    return pixels;
}

void TestBrowserDifferential::probesDrawTheBrowsersPixels_data()
{
    QTest::addColumn<int>("index");
    for (int i = 0; i < m_probes.size(); ++i)
        QTest::newRow(qPrintable(m_probes[i].toObject().value(QStringLiteral("name")).toString()))
            << i;
}

void TestBrowserDifferential::probesDrawTheBrowsersPixels()
{
    QFETCH(int, index);
    const QJsonObject probe = m_probes[index].toObject();
    const QString name = probe.value(QStringLiteral("name")).toString();
    const QString browser = m_browser[name];
    if (probe.value(QStringLiteral("refused")).toBool()) {
        // What the browser refuses PhongLab refuses, with the browser's words.
        QVERIFY2(browser.startsWith(QStringLiteral("error")), qPrintable(browser));
        QString error;
        drawHere(probe, &error);
        QVERIFY2(!error.isEmpty(), qPrintable(name + QStringLiteral(": PhongLab ran it")));
        qInfo("probe %s: refused by both (the browser: %s)", qPrintable(name),
              qPrintable(browser.simplified().left(160)));
        return;
    }
    QVERIFY2(!browser.startsWith(QStringLiteral("error")), qPrintable(browser));
    const QByteArray theirs = QByteArray::fromHex(browser.toLatin1());
    QCOMPARE(theirs.size(), kSide * kSide * 4);
    QString error;
    const QByteArray ours = drawHere(probe, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    int worst = 0;
    int worstAt = 0;
    for (int i = 0; i < theirs.size(); ++i) {
        const int d = std::abs(int(uchar(theirs[i])) - int(uchar(ours[i])));
        if (d > worst) {
            worst = d;
            worstAt = i;
        }
    }
    const QString listed = probe.value(QStringLiteral("differs")).toString();
    const QString where = QStringLiteral("%1: pixel %2, channel %3: browser %4, PhongLab %5")
                              .arg(name)
                              .arg(worstAt / 4)
                              .arg(worstAt % 4)
                              .arg(int(uchar(theirs[worstAt])))
                              .arg(int(uchar(ours[worstAt])));
    if (listed.isEmpty()) {
        QVERIFY2(worst <= kTolerance, qPrintable(where));
        qInfo("probe %s: the browser's pixels (within %d/255)", qPrintable(name), kTolerance);
    } else {
        // The list is this driver's (Mesa llvmpipe: mediump in 16 bits, no
        // clamped index); another GPU may happen to agree with the browser.
        if (m_offscreen.glRendererName().contains(QLatin1String("llvmpipe")))
            QVERIFY2(worst > kTolerance,
                     qPrintable(name
                                + QStringLiteral(" now matches the browser: take it off the "
                                                 "list of probes PhongLab cannot match")));
        qInfo("probe %s: differs, as listed: %s (%s)", qPrintable(name), qPrintable(listed),
              qPrintable(where));
    }
}

QTEST_MAIN(TestBrowserDifferential)
#include "tst_browserdifferential.moc"
