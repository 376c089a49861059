#include "ClassFolder.h"

#include "core/program/ShaderStage.h"
#include "core/project/ProjectPrograms.h"
#include "core/project/ProjectShader.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ClassFolderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::ClassFolder)
};

namespace {

constexpr int kMaxFilesLookedAt = 2000; // a node_modules folder is not a submission
constexpr qint64 kSniffBytes = 256 * 1024;

enum class StageGuess {
    None,
    Vertex,
    Fragment
};

StageGuess stageOf(const QFileInfo &file)
{
    if (const std::optional<ShaderStage> stage = stageOfSuffix(file.fileName()))
        return *stage == ShaderStage::Vertex ? StageGuess::Vertex : StageGuess::Fragment;
    if (!hasShaderFileSuffix(file.fileName()))
        return StageGuess::None;
    QFile f(file.filePath());
    if (!f.open(QIODevice::ReadOnly))
        return StageGuess::Fragment; // read again (and refused, with the reason) by the check
    return f.read(kSniffBytes).contains("gl_Position") ? StageGuess::Vertex : StageGuess::Fragment;
}

QString relativeTo(const QDir &dir, const QString &path)
{
    return dir.relativeFilePath(path);
}

// A file a shader could be read from, by its name alone (nothing is read).
bool looksLikeShader(const QFileInfo &file)
{
    return hasShaderFileSuffix(file.fileName());
}

// Whether `file` is the submission's own: not a symbolic link, and its real
// path inside the submission's real folder. A student's link to a file of
// the teacher's would otherwise be read, quoted in the report and handed
// back with the feedback.
bool isOwnFile(const QFileInfo &file, const QString &realFolder)
{
    if (file.isSymLink())
        return false;
    const QString real = file.canonicalFilePath();
    return !real.isEmpty() && real.startsWith(realFolder + QLatin1Char('/'));
}

bool isPageOrScript(const QFileInfo &file)
{
    return isPageFile(file.fileName()) || isScriptFile(file.fileName());
}

Submission readSubmission(const QFileInfo &folder, bool *isProject)
{
    Submission s;
    s.name = folder.fileName();
    s.folder = folder.absoluteFilePath();
    const QDir dir(s.folder);
    const QString realFolder = folder.canonicalFilePath();
    QStringList vertex, fragment, refused;
    if (folder.isSymLink())
        refused << s.name;
    // System: a dangling link is listed too, and refused with the others.
    QDirIterator it(s.folder, QDir::Files | QDir::System | QDir::NoDotAndDotDot,
                    QDirIterator::Subdirectories);
    for (int seen = 0; !folder.isSymLink() && it.hasNext() && seen < kMaxFilesLookedAt; ++seen) {
        const QFileInfo file(it.next());
        if (file.fileName().startsWith(QLatin1Char('.')))
            continue;
        if (!isOwnFile(file, realFolder)) {
            if (looksLikeShader(file))
                refused << relativeTo(dir, file.absoluteFilePath());
            continue;
        }
        if (isPageOrScript(file))
            *isProject = true;
        switch (stageOf(file)) {
        case StageGuess::Vertex: vertex << file.absoluteFilePath(); break;
        case StageGuess::Fragment: fragment << file.absoluteFilePath(); break;
        case StageGuess::None: break;
        }
    }
    vertex.sort();
    fragment.sort();
    QStringList problems;
    if (!refused.isEmpty()) {
        refused.sort();
        problems << ClassFolderWords::tr("not read: %1 (a symbolic link, or a path that leaves "
                                         "the submission; hand in the file itself)")
                        .arg(refused.join(QStringLiteral(", ")));
    }
    for (const auto &[files, stage] :
         {std::pair{vertex, "vertex"}, std::pair{fragment, "fragment"}})
        if (files.size() > 1) {
            QStringList names;
            for (const QString &f : files)
                names << relativeTo(dir, f);
            problems << ClassFolderWords::tr("%1 files for the %2 stage: %3 (keep one)")
                            .arg(files.size())
                            .arg(QLatin1String(stage), names.join(QStringLiteral(", ")));
        }
    if (vertex.isEmpty() && fragment.isEmpty() && refused.isEmpty())
        problems << ClassFolderWords::tr("no shader file (.vert, .frag, .vs, .fs, .glsl) in %1")
                        .arg(s.name);
    if (vertex.size() > 1 || fragment.size() > 1)
        *isProject = true; // a Gouraud and a Phong pair, say
    if (!refused.isEmpty())
        *isProject = false; // refused whole: nothing more of it is read
    s.error = problems.join(QStringLiteral("; "));
    if (s.error.isEmpty()) {
        s.vertex = vertex.value(0);
        s.fragment = fragment.value(0);
    }
    return s;
}

// A submission read as a WebGL project: one per program that lights. Where
// none does, the files read plainly say more (two fragment shaders and no
// vertex shader), else the project says why.
std::vector<Submission> readProjectSubmission(const Submission &plain)
{
    const Project project = readProject(plain.folder);
    const std::vector<const ProjectProgram *> lit = litPrograms(project);
    if (lit.empty()) {
        Submission s = plain;
        if (s.error.isEmpty() && s.vertex.isEmpty() && s.fragment.isEmpty())
            s.error = project.error.isEmpty()
                ? ClassFolderWords::tr("no program that lights anything (%1)")
                      .arg(project.notes.join(QStringLiteral("; ")))
                : project.error;
        s.notes = project.notes;
        return {s};
    }
    std::vector<Submission> programs;
    for (const ProjectProgram *p : lit) {
        Submission s;
        s.name = plain.name;
        s.folder = plain.folder;
        s.program = p->name;
        s.vertex = shaderLocator(p->vertex);
        s.fragment = shaderLocator(p->fragment);
        s.notes = project.notes;
        programs.push_back(std::move(s));
    }
    return programs;
}

} // namespace

ClassFolder readClassFolder(const QString &path)
{
    ClassFolder out;
    const QFileInfo info(path);
    if (!info.exists()) {
        out.error = ClassFolderWords::tr("%1: no such folder").arg(path);
        return out;
    }
    if (!info.isDir()) {
        out.error = ClassFolderWords::tr("%1: not a folder (one subfolder per submission expected)")
                        .arg(path);
        return out;
    }
    const QFileInfoList folders =
        QDir(path).entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::NoSort);
    for (const QFileInfo &folder : folders) {
        // Moodle's online text beside a file submission is no shader.
        if (folder.fileName().startsWith(QLatin1Char('.'))
            || folder.fileName().contains(QLatin1String("_assignsubmission_onlinetext_")))
            continue;
        bool isProject = false;
        Submission plain = readSubmission(folder, &isProject);
        if (!isProject) {
            out.submissions.push_back(std::move(plain));
            continue;
        }
        for (Submission &s : readProjectSubmission(plain))
            out.submissions.push_back(std::move(s));
    }
    std::sort(out.submissions.begin(), out.submissions.end(),
              [](const Submission &a, const Submission &b) {
                  return std::pair(a.name, a.program) < std::pair(b.name, b.program);
              });
    if (out.submissions.empty())
        out.error = ClassFolderWords::tr(
                        "%1: no submission folders in it (one subfolder per student expected)")
                        .arg(path);
    return out;
}

} // namespace phonglab::cli
