#include "GradePages.h"

#include "cli/common/CliCommon.h"
#include "render/page/PageCheckOutput.h"

#include <QCoreApplication>
#include <QDir>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentMap>

#include <map>

namespace phonglab::cli {

struct GradePagesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::GradePages)
};

namespace {

// The submissions of each project folder (a project's programs are
// submissions of their own; its page runs once).
std::map<QString, std::vector<std::size_t>> submissionsByFolder(const GradeResults &results)
{
    std::map<QString, std::vector<std::size_t>> out;
    for (std::size_t i = 0; i < results.submissions.size(); ++i) {
        const Submission &s = results.submissions[i];
        if (s.error.isEmpty() && choosePageFile(s.folder, {}).ok())
            out[s.folder].push_back(i);
    }
    return out;
}

SubmissionPage summaryOf(const PageCheck &check, const QString &relativeFolder)
{
    SubmissionPage page;
    page.error = check.error;
    page.json = pageJson(check);
    if (!check.ok())
        return page;
    if (check.fidelity) {
        page.largestDifference = check.fidelity->largestOutsideEdges;
        page.faithful = check.fidelity->faithful() && check.notReplayed.isEmpty();
    }
    for (const JavaScriptFinding &f : check.javascript)
        if (f.mistake)
            page.mistakes << f.key + QLatin1Char(' ') + f.subject;
    if (check.ownScene && check.ownScene->comparable()) {
        page.ownScene = check.ownScene->passed() ? QStringLiteral("pass") : QStringLiteral("fail");
        page.exactImage = relativeFolder + QStringLiteral("/exact.png");
        page.heatmapImage = relativeFolder + QStringLiteral("/heatmap.png");
    }
    if (!check.capture.pixels.isEmpty()) {
        page.browserImage = relativeFolder + QStringLiteral("/browser.png");
        page.phonglabImage = check.replayPixels.isEmpty()
            ? QString()
            : relativeFolder + QStringLiteral("/phonglab.png");
        page.differenceImage = check.replayPixels.isEmpty()
            ? QString()
            : relativeFolder + QStringLiteral("/difference.png");
    }
    return page;
}

// The page's program and values on the submissions of its folder: the one
// whose stages the page compiled unchanged, else the project's only one.
void takePageProgram(GradeResults &results, const std::vector<std::size_t> &members,
                     const PageStages &stages)
{
    if (stages.vertexPath.isEmpty())
        return;
    for (std::size_t i : members) {
        Submission &s = results.submissions[i];
        const bool same = s.vertex == stages.vertexPath && s.fragment == stages.fragmentPath;
        if (!same && members.size() > 1)
            continue;
        if (!same) {
            s.vertex = stages.vertexPath;
            s.fragment = stages.fragmentPath;
            s.notes << stages.note;
        }
        s.pageConstants = stages.constants;
    }
}

} // namespace

void runSubmissionPages(GradeResults &results, const PageRequest &request, int jobs)
{
    results.pages.assign(results.submissions.size(), std::nullopt);
    const std::map<QString, std::vector<std::size_t>> folders = submissionsByFolder(results);
    std::vector<std::pair<QString, QString>> runs; // folder, its out folder
    for (const auto &[folder, members] : folders)
        runs.emplace_back(folder,
                          QStringLiteral("pages/") + results.submissions[members.front()].name);
    std::vector<PageRequest> requests;
    for (const auto &[folder, out] : runs) {
        PageRequest r = request;
        r.run.folders.project = folder;
        r.outFolder = QDir(results.settings.outFolder).filePath(out);
        requests.push_back(r);
    }
    QThreadPool pool;
    pool.setMaxThreadCount(std::max(1, jobs));
    std::atomic<int> done = 0;
    const int total = int(requests.size());
    const std::vector<PageCapturing> captured =
        QtConcurrent::blockingMapped<std::vector<PageCapturing>>(
            &pool, requests, [&done, total](const PageRequest &r) {
                PageCapturing c = capturePage(r);
                printErrLine(
                    GradePagesWords::tr("grade: page %1 of %2 run").arg(++done).arg(total));
                return c;
            });
    for (std::size_t k = 0; k < requests.size(); ++k) {
        const PageCheck check = checkCapturedPage(captured[k], requests[k]);
        if (const QString unwritten = writePageOutputs(check, requests[k].outFolder);
            !unwritten.isEmpty())
            printError(unwritten);
        const std::vector<std::size_t> &members = folders.at(runs[k].first);
        const SubmissionPage summary = summaryOf(check, runs[k].second);
        for (std::size_t i : members)
            results.pages[i] = summary;
        if (check.ok())
            takePageProgram(results, members,
                            pageStagesForScene(check, runs[k].first, requests[k].outFolder));
    }
}

} // namespace phonglab::cli
