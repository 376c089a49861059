#include "PageRun.h"

#include "BrowserPipe.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QUrl>

#include <memory>

namespace phonglab {

struct PageRunWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageRun)
};

namespace {

constexpr qint64 kMaxServedBytes = 64 * 1024 * 1024;
// The browser's own start (a cold Chromium on a busy machine); the page's
// time limit starts once it is up.
constexpr qint64 kBrowserStartMs = 30000;

QString str(const char *text)
{
    return QString::fromLatin1(text);
}

QStringList browserArguments(const PageRunOptions &options, const QString &profile)
{
    return {str("--headless=new"), str("--no-sandbox"), str("--use-angle=swiftshader"),
            str("--enable-unsafe-swiftshader"), str("--no-first-run"),
            str("--no-default-browser-check"), str("--disable-background-networking"),
            str("--disable-component-update"), str("--disable-sync"), str("--disable-extensions"),
            str("--disable-default-apps"), str("--mute-audio"),
            str("--force-device-scale-factor=1"),
            // Nothing resolves: what PageRun does not answer reaches no one.
            str("--host-resolver-rules=MAP * ~NOTFOUND"),
            QStringLiteral("--window-size=%1,%2")
                .arg(options.window.width())
                .arg(options.window.height()),
            str("--user-data-dir=") + profile, str("about:blank")};
}

QString captureScript(const PageRunOptions &options)
{
    QFile file(QStringLiteral(":/app/core/page/capture.js"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QJsonObject config{{QStringLiteral("seed"), qint64(options.seed)}};
    return QStringLiteral("window.__phonglabConfig = %1;\n")
               .arg(QString::fromUtf8(QJsonDocument(config).toJson(QJsonDocument::Compact)))
        + QString::fromUtf8(file.readAll());
}

// Answers the page's requests from its folders (core/page/PageServer) and
// keeps the list.
class RequestAnswers
{
public:
    RequestAnswers(BrowserPipe *pipe, const PageFolders &folders)
        : m_pipe(pipe)
        , m_folders(folders)
    {
    }

    void answer(const QJsonObject &params, const QString &session)
    {
        const QString id = params.value(str("requestId")).toString();
        const QString url = params.value(str("request")).toObject().value(str("url")).toString();
        const ServedFile served = serveRequest(m_folders, url);
        QFile file(served.path);
        if (served.served() && file.size() <= kMaxServedBytes && file.open(QIODevice::ReadOnly)) {
            const QJsonArray headers{
                QJsonObject{{str("name"), str("Content-Type")}, {str("value"), served.mime}},
                QJsonObject{{str("name"), str("Access-Control-Allow-Origin")},
                            {str("value"), str("*")}},
                QJsonObject{{str("name"), str("Cache-Control")}, {str("value"), str("no-store")}}};
            m_pipe->send(str("Fetch.fulfillRequest"),
                         {{str("requestId"), id},
                          {str("responseCode"), 200},
                          {str("responseHeaders"), headers},
                          {str("body"), QString::fromLatin1(file.readAll().toBase64())}},
                         session);
            m_requests.push_back({url, served.path, {}});
            return;
        }
        m_pipe->send(str("Fetch.failRequest"),
                     {{str("requestId"), id}, {str("errorReason"), str("BlockedByClient")}},
                     session);
        // The browser asks for a page's icon by itself: not the page's doing.
        if (!url.endsWith(str("/favicon.ico")))
            m_requests.push_back(
                {url,
                 {},
                 served.served() ? PageRunWords::tr("larger than 64 MB") : served.refusal});
    }

    std::vector<PageFetch> requests() const { return m_requests; }

private:
    BrowserPipe *m_pipe;
    PageFolders m_folders;
    std::vector<PageFetch> m_requests;
};

Result<QString> openPageSession(BrowserPipe &pipe)
{
    const Result<QJsonObject> target =
        pipe.call(str("Target.createTarget"), {{str("url"), str("about:blank")}});
    if (!target)
        return fail(target.error());
    const Result<QJsonObject> attached =
        pipe.call(str("Target.attachToTarget"),
                  {{str("targetId"), target->value(str("targetId"))}, {str("flatten"), true}});
    if (!attached)
        return fail(attached.error());
    return attached->value(str("sessionId")).toString();
}

Result<> prepareSession(BrowserPipe &pipe, const QString &session, const PageRunOptions &options,
                        const QString &script)
{
    const std::vector<std::pair<QString, QJsonObject>> commands{
        {str("Page.enable"), {}},
        {str("Fetch.enable"),
         {{str("patterns"), QJsonArray{QJsonObject{{str("urlPattern"), str("*")}}}}}},
        {str("Emulation.setTimezoneOverride"), {{str("timezoneId"), str("UTC")}}},
        {str("Emulation.setLocaleOverride"), {{str("locale"), str("en-US")}}},
        {str("Emulation.setDeviceMetricsOverride"),
         {{str("width"), options.window.width()},
          {str("height"), options.window.height()},
          {str("deviceScaleFactor"), 1},
          {str("mobile"), false}}},
        {str("Page.addScriptToEvaluateOnNewDocument"), {{str("source"), script}}},
    };
    for (const auto &[method, params] : commands)
        if (const Result<QJsonObject> done = pipe.call(method, params, session); !done)
            return fail(done.error());
    return {};
}

QString evaluationError(const QJsonObject &result)
{
    const QJsonObject details = result.value(str("exceptionDetails")).toObject();
    return details.value(str("exception"))
        .toObject()
        .value(str("description"))
        .toString(details.value(str("text")).toString());
}

// A served file as the report names it: relative to the project, or to
// the library folder it came from.
QString servedName(const QString &file, const PageFolders &folders)
{
    const QString project = QFileInfo(folders.project).canonicalFilePath();
    if (file.startsWith(project + QLatin1Char('/')))
        return file.mid(project.size() + 1);
    for (const QString &library : folders.libraries) {
        const QString root = QFileInfo(library).canonicalFilePath();
        if (file.startsWith(root + QLatin1Char('/')))
            return QFileInfo(root).fileName() + QLatin1Char('/') + file.mid(root.size() + 1);
    }
    return QFileInfo(file).fileName();
}

// The page's capture with what PageRun knows beside it: the page, the files
// served, the requests refused.
QByteArray withRequests(const QByteArray &capture, const QString &page,
                        const std::vector<PageFetch> &requests, const PageFolders &folders)
{
    QJsonObject o = QJsonDocument::fromJson(capture).object();
    o.insert(str("page"), page);
    QJsonArray served;
    QJsonArray refused = o.value(str("refused")).toArray();
    for (const PageFetch &r : requests) {
        if (!r.file.isEmpty())
            served.append(servedName(r.file, folders));
        else
            refused.append(QJsonObject{
                {str("kind"), str("request")}, {str("url"), r.url}, {str("why"), r.refusal}});
    }
    o.insert(str("served"), served);
    o.insert(str("refused"), refused);
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

// The throwaway profile's folder: under the run's work folder where it has
// one.
std::unique_ptr<QTemporaryDir> makeProfileFolder(const QString &workFolder)
{
    if (workFolder.isEmpty())
        return std::make_unique<QTemporaryDir>();
    return std::make_unique<QTemporaryDir>(QDir(workFolder).filePath(str("browser-XXXXXX")));
}

QMap<QString, QString> browserEnvironment(const QString &home)
{
    return {{str("HOME"), home},
            {str("XDG_CONFIG_HOME"), home + str("/config")},
            {str("XDG_CACHE_HOME"), home + str("/cache")},
            {str("TZ"), str("UTC")},
            {str("LANG"), str("C.UTF-8")}};
}

// Whether the student's page has loaded, from the browser's page events.
struct PageLoad {
    bool navigated = false;
    bool loaded = false;

    void see(const QString &method, const QJsonObject &params)
    {
        // about:blank's own load may come after Page.enable: only the
        // student's page, once the main frame has gone to it, counts.
        if (method == str("Page.frameNavigated")
            && !params.value(str("frame")).toObject().contains(str("parentId")))
            navigated = params.value(str("frame"))
                            .toObject()
                            .value(str("url"))
                            .toString()
                            .startsWith(kPageOrigin);
        else if (method == str("Page.loadEventFired") && navigated)
            loaded = true;
    }
};

// Each part of the page's path percent-encoded: a page named "50%.html"
// or "a#b.html" is a file, not a fragment.
QString pageUrl(const QString &page)
{
    QStringList parts;
    for (const QString &part : page.split(QLatin1Char('/')))
        parts << QString::fromLatin1(QUrl::toPercentEncoding(part));
    return kPageOrigin + QLatin1Char('/') + parts.join(QLatin1Char('/'));
}

// Navigates to the page, its time limit starting now, and waits for its load.
Result<> openPage(BrowserPipe &pipe, const QString &session, const PageRunOptions &options,
                  const QString &page, const PageLoad &load)
{
    const QString url = pageUrl(page);
    pipe.restartTimeLimit(options.timeLimitMs);
    const Result<QJsonObject> navigation =
        pipe.call(str("Page.navigate"), {{str("url"), url}}, session);
    if (!navigation)
        return fail(navigation.error());
    if (const QString error = navigation->value(str("errorText")).toString(); !error.isEmpty())
        return fail(PageRunWords::tr("the page %1 could not be opened: %2").arg(page, error));
    if (const Result<> waited = pipe.waitUntil([&] { return load.loaded; }); !waited)
        return fail(waited.error());
    return {};
}

// Runs capture.js's steps and frames in the page; its JSON text.
Result<QString> evaluateCapture(BrowserPipe &pipe, const QString &session,
                                const PageRunOptions &options)
{
    const QString run =
        QStringLiteral("window.__phonglab ? window.__phonglab.run(%1, %2) : null")
            .arg(options.frames)
            .arg(QString::fromUtf8(QJsonDocument(QJsonArray::fromStringList(options.steps))
                                       .toJson(QJsonDocument::Compact)));
    const Result<QJsonObject> evaluated = pipe.call(
        str("Runtime.evaluate"),
        {{str("expression"), run}, {str("awaitPromise"), true}, {str("returnByValue"), true}},
        session);
    if (!evaluated)
        return fail(evaluated.error());
    if (evaluated->contains(str("exceptionDetails")))
        return fail(PageRunWords::tr("the capture failed: %1").arg(evaluationError(*evaluated)));
    const QJsonValue value = evaluated->value(str("result")).toObject().value(str("value"));
    if (!value.isString())
        return fail(PageRunWords::tr("the page's document was replaced before it could be "
                                     "captured"));
    return value.toString();
}

} // namespace

QString browserMissingMessage()
{
    return PageRunWords::tr("running the page needs Chromium, which is not installed "
                            "(sudo apt install chromium; scripts/setup.sh installs it); "
                            "the shaders are still read from the files");
}

Result<QString> choosePageFile(const QString &project, const QString &pageFile)
{
    const QDir dir(project);
    if (!dir.exists())
        return fail(PageRunWords::tr("%1: no such folder").arg(project));
    if (!pageFile.isEmpty()) {
        if (!QFileInfo(dir.filePath(pageFile)).isFile())
            return fail(PageRunWords::tr("%1: no page %2 in the project").arg(project, pageFile));
        return pageFile;
    }
    if (QFileInfo(dir.filePath(str("index.html"))).isFile())
        return str("index.html");
    const QStringList pages = dir.entryList({str("*.html"), str("*.htm")}, QDir::Files, QDir::Name);
    if (pages.size() == 1)
        return pages.first();
    if (pages.isEmpty())
        return fail(PageRunWords::tr("%1: no HTML page in the project").arg(project));
    return fail(PageRunWords::tr("%1: which page? it has %2 (choose one with --page-file)")
                    .arg(project, pages.join(str(", "))));
}

Result<PageRunOutput> runPage(const PageRunOptions &options)
{
    PageRunOutput output;
    const Result<QString> page = choosePageFile(options.folders.project, options.pageFile);
    if (!page)
        return fail(page.error());
    output.pageFile = *page;
    const QString browser = options.browser.isEmpty() ? BrowserPipe::executable() : options.browser;
    if (browser.isEmpty())
        return fail(browserMissingMessage());
    const QString script = captureScript(options);
    if (script.isEmpty())
        return fail(str("capture.js is missing from the build"));

    const std::unique_ptr<QTemporaryDir> temporary = makeProfileFolder(options.workFolder);
    if (!temporary->isValid())
        return fail(PageRunWords::tr("cannot make a folder for the browser's profile"));
    const QString home = temporary->path();
    const QMap<QString, QString> environment = browserEnvironment(home);

    BrowserPipe pipe;
    if (const Result<> started =
            pipe.start(browser, browserArguments(options, home + str("/profile")), environment,
                       home + str("/browser.log"), kBrowserStartMs);
        !started)
        return fail(started.error());
    pipe.cancelled = options.cancelled;
    RequestAnswers answers(&pipe, options.folders);
    PageLoad load;
    pipe.onEvent = [&](const QString &method, const QJsonObject &params, const QString &session) {
        if (method == str("Fetch.requestPaused"))
            answers.answer(params, session);
        else
            load.see(method, params);
    };
    const auto failed = [&](const QString &why) -> Result<PageRunOutput> {
        pipe.stop();
        return fail(why);
    };
    const Result<QString> session = openPageSession(pipe);
    if (!session)
        return failed(session.error());
    if (const Result<> ready = prepareSession(pipe, *session, options, script); !ready)
        return failed(ready.error());
    if (const Result<> opened = openPage(pipe, *session, options, *page, load); !opened)
        return failed(opened.error());
    const Result<QString> capture = evaluateCapture(pipe, *session, options);
    if (!capture)
        return failed(capture.error());
    output.requests = answers.requests();
    output.capture = withRequests(capture->toUtf8(), *page, output.requests, options.folders);
    pipe.stop();
    output.milliseconds = pipe.elapsedMs();
    return output;
}

} // namespace phonglab
