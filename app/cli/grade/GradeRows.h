#pragma once
#include "ClassFolder.h"
#include "cli/common/SceneOverrides.h"
#include "core/reference/PhongEquation.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"
#include "render/check/CheckReportOutput.h"

#include <QJsonObject>
#include <QSize>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

namespace phonglab::cli {

// What `phonglab grade` works through and what it found: the scenes, the
// submissions, and one row per submission × scene.

struct GradeSettings {
    QString classFolder; // SUBMISSIONS, as given
    QString classRoot;   // the folder the submissions were read from (unpacked/ for an archive)
    QString outFolder;   // --out
    QSize size{800, 600};
    int toleranceSteps = 2;
    std::optional<PhongEquation> equation;
    SceneOverrides overrides; // --bind, --define, --precision over each scene's
};

struct GradeScene {
    QString path;  // as given
    QString label; // its file name; the path as given where two scenes share a name
    QString slug;  // for image file names
    Scene scene;   // with --bind applied
    std::vector<std::shared_ptr<const MeshData>> objectMeshes;
};

struct GradeRow {
    int submission = 0;               // index into the submissions
    int scene = 0;                    // index into the scenes
    Verdict verdict = Verdict::Error; // the row's one verdict
    // What the check found, as `check` reports it but for the verdict;
    // paths in the class folder relative to it.
    CheckFindings findings;
    double seconds = 0.0; // the child's wall time
    // Relative to the out folder; empty where there is none.
    QString yoursImage;
    QString exactImage;
    QString heatmapImage;
};

// What grade --pages found on a submission's page (cli/grade/GradePages):
// the same for each of its rows.
struct SubmissionPage {
    QString error;                        // the page could not be run
    std::optional<int> largestDifference; // fidelity: outside edges, 8-bit steps
    bool faithful = false;
    QStringList mistakes; // the JavaScript half's, "KEY SUBJECT" ("normals-face cloud.obj")
    QString ownScene;     // the own scene's verdict: "pass", "fail", or empty where not checked
    QJsonObject json;     // check --json's "page"
    // Relative to the out folder; empty where there is none.
    QString browserImage;
    QString phonglabImage;
    QString differenceImage;
    QString exactImage;   // the own scene's exact image
    QString heatmapImage; // the browser's frame against it
};

struct GradeResults {
    GradeSettings settings;
    std::vector<Submission> submissions;
    std::vector<GradeScene> scenes;
    std::vector<GradeRow> rows; // by submission, then scene: the same order on every run
    // By submission; empty without --pages, nullopt where a submission has no page.
    std::vector<std::optional<SubmissionPage>> pages;

    const SubmissionPage *pageOf(const GradeRow &row) const;
};

// The row's first finding, or nullptr (pass, error, unexplained fail).
const MistakeFinding *topFinding(const GradeRow &row);
// The mistake key a row is filed under: the top finding's, "unknown" for a
// fail nothing explains, empty otherwise.
QString rowMistakeKey(const GradeRow &row);
// Every mistake the row is explained by, keys space-separated: the smallest
// set that explains it (MistakeSets), else "unknown"; empty unless it failed.
QString rowMistakeKeys(const GradeRow &row);
// Where to look: the top finding's first line, else the first error's
// place. Empty file where there is none.
struct RowPlace {
    QString file;
    int line = 0;
};
RowPlace rowPlace(const GradeRow &row);

// Characters safe in a file name on every system: the rest become '_'.
QString fileSlug(const QString &text);

// The row's files named within `folder` (a course platform's download
// folder of the student), as the student named them: "index.html", not
// "Mia Schulz_20433_assignsubmission_file_/index.html".
void nameFilesWithin(GradeRow &row, const QString &folder);
// How a report names a submission: a course platform's student by their
// name and number, else the folder's name; a project's program after it.
QString shownSubmissionName(const Submission &submission);

} // namespace phonglab::cli
