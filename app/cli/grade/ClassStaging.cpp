#include "ClassStaging.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ClassStagingWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::ClassStaging)
};

namespace {

constexpr int kMaxFilesCopied = 20000;

QFileInfoList entries(const QString &folder)
{
    return QDir(folder).entryInfoList(
        QDir::AllEntries | QDir::System | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

// A copy of `from` into `to`: plain files and folders, never a link.
bool copyTree(const QString &from, const QString &to, int *budget)
{
    if (!QDir().mkpath(to))
        return false;
    for (const QFileInfo &e : entries(from)) {
        if (e.isSymLink() || --*budget < 0)
            continue;
        const QString target = QDir(to).filePath(e.fileName());
        if (e.isDir()) {
            if (!copyTree(e.filePath(), target, budget))
                return false;
        } else if (e.isFile() && !QFile::copy(e.filePath(), target)) {
            return false;
        }
    }
    return true;
}

// One level of wrapping (a zip of the class folder): its only folder.
QString unwrapped(const QString &root)
{
    const QFileInfoList all = entries(root);
    if (all.size() == 1 && all.front().isDir() && !all.front().isSymLink()
        && !moodleName(all.front().fileName())) {
        bool onlyFolders = true;
        for (const QFileInfo &e : entries(all.front().filePath()))
            onlyFolders = onlyFolders && e.isDir();
        if (onlyFolders)
            return all.front().filePath();
    }
    return root;
}

bool hasFlatMoodleFiles(const QString &root)
{
    for (const QFileInfo &e : entries(root))
        if (e.isFile() && !e.isSymLink())
            if (const auto m = moodleName(e.fileName()); m && !m->rest.isEmpty())
                return true;
    return false;
}

bool hasArchives(const QString &root)
{
    QDirIterator it(root, QDir::Files | QDir::NoDotAndDotDot, QDirIterator::Subdirectories);
    for (int seen = 0; it.hasNext() && seen < kMaxFilesCopied; ++seen)
        if (isArchivePath(it.next()) && !it.fileInfo().isSymLink())
            return true;
    return false;
}

// Flat Moodle files into their students' folders; folders as they are.
bool regroup(const QString &from, const QString &to, int *budget)
{
    for (const QFileInfo &e : entries(from)) {
        if (e.isSymLink() || --*budget < 0)
            continue;
        const std::optional<MoodleName> m = moodleName(e.fileName());
        if (e.isFile() && m && !m->rest.isEmpty()) {
            const QString folder = QDir(to).filePath(m->folder());
            if (!QDir().mkpath(folder)
                || !QFile::copy(e.filePath(), QDir(folder).filePath(m->rest)))
                return false;
        } else if (e.isDir()) {
            if (!copyTree(e.filePath(), QDir(to).filePath(e.fileName()), budget))
                return false;
        }
    }
    return true;
}

// A student's own archives, once: what they hold is not opened again (the
// list is made before any is unpacked). A refused one is that student's error.
void unpackStudentArchives(const QFileInfo &folder, const ArchiveLimits &limits,
                           StagedClass *staged)
{
    QStringList archives;
    QDirIterator it(folder.filePath(), QDir::Files | QDir::NoDotAndDotDot,
                    QDirIterator::Subdirectories);
    for (int seen = 0; it.hasNext() && seen < kMaxFilesCopied; ++seen)
        if (isArchivePath(it.next()) && !it.fileInfo().isSymLink())
            archives << it.filePath();
    for (const QString &archive : archives) {
        const Result<UnpackedArchive> done =
            unpackArchive(archive, archive + QStringLiteral(".unpacked"), limits);
        if (!done)
            staged->refused.insert(folder.fileName(), done.error());
    }
}

} // namespace

QString MoodleName::folder() const
{
    return QStringLiteral("%1_%2_assignsubmission_%3_").arg(student, participant, plugin);
}

std::optional<MoodleName> moodleName(const QString &name)
{
    static const QRegularExpression pattern(
        QStringLiteral("^(.+)_(\\d+)_assignsubmission_([a-z]+)_(.*)$"));
    const QRegularExpressionMatch m = pattern.match(name);
    if (!m.hasMatch())
        return std::nullopt;
    return MoodleName{m.captured(1), m.captured(2), m.captured(3), m.captured(4)};
}

StagedClass stageClass(const QString &submissions, const QString &outFolder,
                       const ArchiveLimits &limits)
{
    StagedClass staged;
    const QString unpacked = QDir(outFolder).filePath(QStringLiteral("unpacked"));
    const QFileInfo input(submissions);
    QString root = input.absoluteFilePath();
    bool ours = false; // a folder PhongLab made, which it may write into
    if (input.isFile() && isArchivePath(submissions)) {
        const QString into = QDir(unpacked).filePath(QStringLiteral("class"));
        QDir(into).removeRecursively();
        if (const Result<UnpackedArchive> done = unpackArchive(submissions, into, limits); !done) {
            staged.error = done.error();
            return staged;
        }
        root = unwrapped(into);
        ours = true;
    } else if (!input.isDir()) {
        staged.root = submissions; // readClassFolder says what is wrong with it
        return staged;
    }
    int budget = kMaxFilesCopied;
    if (hasFlatMoodleFiles(root)) {
        const QString into = QDir(unpacked).filePath(QStringLiteral("moodle"));
        QDir(into).removeRecursively();
        if (!regroup(root, into, &budget)) {
            staged.error = ClassStagingWords::tr("%1: cannot regroup the files into %2")
                               .arg(submissions, into);
            return staged;
        }
        root = into;
        ours = true;
    }
    if (!ours && hasArchives(root)) {
        const QString into = QDir(unpacked).filePath(QStringLiteral("class"));
        QDir(into).removeRecursively();
        if (!copyTree(root, into, &budget)) {
            staged.error =
                ClassStagingWords::tr("%1: cannot copy it into %2").arg(submissions, into);
            return staged;
        }
        root = into;
        ours = true;
    }
    staged.root = root;
    for (const QFileInfo &folder : entries(root)) {
        if (!folder.isDir() || folder.isSymLink())
            continue;
        if (const auto m = moodleName(folder.fileName()))
            staged.origins.insert(folder.fileName(), {m->student, m->participant});
        if (!ours)
            continue;
        unpackStudentArchives(folder, limits, &staged);
    }
    return staged;
}

} // namespace phonglab::cli
