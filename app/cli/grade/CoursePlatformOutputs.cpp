#include "CoursePlatformOutputs.h"

#include "GradeReport.h"

#include <QCoreApplication>
#include <QFile>
#include <QRegularExpression>
#include <QSet>

#include <archive.h>
#include <archive_entry.h>

#include <cmath>
#include <map>
#include <memory>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct CoursePlatformWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::CoursePlatformOutputs)
};

namespace {

// The submissions of one student: their folder's, every program.
std::vector<int> submissionsOf(const GradeResults &results, const QString &folder)
{
    std::vector<int> out;
    for (std::size_t i = 0; i < results.submissions.size(); ++i)
        if (results.submissions[i].name == folder)
            out.push_back(int(i));
    return out;
}

// The students that came from Moodle, once each, in the submissions' order.
std::vector<int> moodleStudents(const GradeResults &results)
{
    std::vector<int> first;
    QSet<QString> seen;
    for (std::size_t i = 0; i < results.submissions.size(); ++i) {
        const Submission &s = results.submissions[i];
        if (!s.participant.isEmpty() && !seen.contains(s.name)) {
            seen.insert(s.name);
            first.push_back(int(i));
        }
    }
    return first;
}

QString quotedField(const QString &text)
{
    QString t = text;
    // A spreadsheet opening the sheet runs no formula of a student's.
    if (!t.isEmpty() && QStringLiteral("=+-@").contains(t.front()))
        t.prepend(QLatin1Char('\''));
    return QLatin1Char('"') + t.replace(QLatin1Char('"'), QStringLiteral("\"\""))
        + QLatin1Char('"');
}

QString number(double value)
{
    return QString::number(value, 'f', 2).remove(QRegularExpression(QStringLiteral("\\.?0+$")));
}

QString sentence(const GradeResults &results, const GradeRow &row, bool namePrograms)
{
    const Submission &s = results.submissions[std::size_t(row.submission)];
    QString where = results.scenes[std::size_t(row.scene)].label;
    if (namePrograms && !s.program.isEmpty())
        where += QStringLiteral(" (%1)").arg(s.program);
    switch (row.verdict) {
    case Verdict::Pass: return CoursePlatformWords::tr("%1: matches the exact image.").arg(where);
    case Verdict::Fail: {
        const QString key = rowMistakeKey(row);
        return key.isEmpty() || key == QLatin1String("unknown")
            ? CoursePlatformWords::tr("%1: differs from the exact image; no classic mistake "
                                      "explains it.")
                  .arg(where)
            : CoursePlatformWords::tr("%1: differs from the exact image, most likely %2.")
                  .arg(where, key);
    }
    case Verdict::Error: {
        const RowPlace place = rowPlace(row);
        QString message =
            row.findings.errors.empty() ? QString() : row.findings.errors.front().message;
        if (!message.endsWith(QLatin1Char('.')))
            message += QLatin1Char('.');
        // The student's own file, as they named it, not the download's folder.
        QString file = place.file;
        if (file.startsWith(s.name + QLatin1Char('/')))
            file.remove(0, s.name.size() + 1);
        return place.line > 0 ? CoursePlatformWords::tr("%1: not checked, %2 line %3: %4")
                                    .arg(where, file)
                                    .arg(place.line)
                                    .arg(message)
                              : CoursePlatformWords::tr("%1: not checked: %2").arg(where, message);
    }
    case Verdict::Timeout:
        return CoursePlatformWords::tr("%1: took longer than the time allowed.").arg(where);
    case Verdict::Crash:
        return CoursePlatformWords::tr("%1: the check crashed or ran out of memory.").arg(where);
    }
    return {};
}

// Only this student's submissions and rows, for a report of their own.
GradeResults onlyStudent(const GradeResults &results, const QString &folder)
{
    GradeResults one;
    one.settings = results.settings;
    // The student by name, their files by their own names: the download's
    // folder and the teacher's paths stay with the teacher.
    const QString student =
        results.submissions[std::size_t(submissionsOf(results, folder).front())].student;
    one.settings.classFolder = student.isEmpty() ? folder : student;
    one.scenes = results.scenes;
    std::map<int, int> index;
    for (const int s : submissionsOf(results, folder)) {
        index[s] = int(one.submissions.size());
        Submission copy = results.submissions[std::size_t(s)];
        copy.vertex.clear(); // the teacher's command to open it names the teacher's paths
        copy.fragment.clear();
        if (!copy.student.isEmpty())
            copy.name = copy.student;
        one.submissions.push_back(std::move(copy));
        if (const std::size_t k = std::size_t(s); k < results.pages.size()) {
            one.pages.resize(one.submissions.size());
            one.pages.back() = results.pages[k];
        }
    }
    for (const GradeRow &row : results.rows)
        if (const auto it = index.find(row.submission); it != index.end()) {
            GradeRow copy = row;
            copy.submission = it->second;
            nameFilesWithin(copy, folder);
            one.rows.push_back(std::move(copy));
        }
    return one;
}

struct WriterCloser {
    void operator()(archive *a) const
    {
        archive_write_close(a);
        archive_write_free(a);
    }
};

bool addFile(archive *a, const QString &name, const QByteArray &bytes)
{
    std::unique_ptr<archive_entry, decltype(&archive_entry_free)> entry(archive_entry_new(),
                                                                        &archive_entry_free);
    archive_entry_set_pathname_utf8(entry.get(), name.toUtf8().constData());
    archive_entry_set_filetype(entry.get(), AE_IFREG);
    archive_entry_set_perm(entry.get(), 0644);
    archive_entry_set_size(entry.get(), bytes.size());
    return archive_write_header(a, entry.get()) == ARCHIVE_OK
        && archive_write_data(a, bytes.constData(), std::size_t(bytes.size())) == bytes.size();
}

} // namespace

double GradePoints::of(Verdict verdict) const
{
    switch (verdict) {
    case Verdict::Pass: return pass;
    case Verdict::Fail: return fail;
    case Verdict::Error: return error;
    case Verdict::Timeout: return timeout;
    case Verdict::Crash: return crash;
    }
    return 0.0;
}

Result<GradePoints> parseGradePoints(const QString &text)
{
    GradePoints points;
    for (const QString &item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString name = item.section(QLatin1Char('='), 0, 0).trimmed();
        bool ok = false;
        const double value = item.section(QLatin1Char('='), 1).trimmed().toDouble(&ok);
        double *slot = name == QLatin1String("pass") ? &points.pass
            : name == QLatin1String("fail")          ? &points.fail
            : name == QLatin1String("error")         ? &points.error
            : name == QLatin1String("timeout")       ? &points.timeout
            : name == QLatin1String("crash")         ? &points.crash
                                                     : nullptr;
        if (!slot || !ok || !item.contains(QLatin1Char('=')) || !std::isfinite(value))
            return fail(
                CoursePlatformWords::tr("--points: expected VERDICT=NUMBER, … with the "
                                        "verdicts pass, fail, error, timeout, crash; got '%1'")
                    .arg(item));
        *slot = value;
    }
    return points;
}

QString feedbackComment(const GradeResults &results, int submission)
{
    const QString folder = results.submissions[std::size_t(submission)].name;
    // A project's program is named where the student has several.
    const bool namePrograms = submissionsOf(results, folder).size() > 1;
    QStringList sentences;
    for (const GradeRow &row : results.rows)
        if (results.submissions[std::size_t(row.submission)].name == folder)
            sentences << sentence(results, row, namePrograms);
    return sentences.join(QLatin1Char(' '));
}

QByteArray moodleGradesCsv(const GradeResults &results, const GradePoints &points)
{
    const std::vector<int> students = moodleStudents(results);
    if (students.empty())
        return {};
    QString csv = QStringLiteral("\"Identifier\",\"Full name\",\"Grade\",\"Feedback comments\"\n");
    for (const int first : students) {
        const Submission &s = results.submissions[std::size_t(first)];
        double grade = 0.0;
        for (const GradeRow &row : results.rows)
            if (results.submissions[std::size_t(row.submission)].name == s.name)
                grade += points.of(row.verdict);
        csv += QStringList{quotedField(QStringLiteral("Participant ") + s.participant),
                           quotedField(s.student), quotedField(number(grade)),
                           quotedField(feedbackComment(results, first))}
                   .join(QLatin1Char(','))
            + QLatin1Char('\n');
    }
    return csv.toUtf8();
}

// The pictures a row's feedback shows: the check's, and the page's frames.
QStringList rowImages(const GradeResults &results, const GradeRow &row)
{
    QStringList images{row.yoursImage, row.exactImage, row.heatmapImage};
    if (const SubmissionPage *page = results.pageOf(row))
        images << page->browserImage << page->exactImage << page->heatmapImage
               << page->phonglabImage << page->differenceImage;
    return images;
}

Result<> writeFeedbackZip(const GradeResults &results, const QString &zipPath)
{
    const std::vector<int> students = moodleStudents(results);
    QFile::remove(zipPath);
    if (students.empty())
        return {};
    std::unique_ptr<archive, WriterCloser> a(archive_write_new());
    archive_write_set_format_zip(a.get());
    archive_write_set_options(a.get(), "zip:hdrcharset=UTF-8");
    if (archive_write_open_filename(a.get(), QFile::encodeName(zipPath).constData()) != ARCHIVE_OK)
        return fail(CoursePlatformWords::tr("%1: cannot write: %2")
                        .arg(zipPath, QString::fromLocal8Bit(archive_error_string(a.get()))));
    const QString out = results.settings.outFolder + QLatin1Char('/');
    for (const int first : students) {
        const QString folder = results.submissions[std::size_t(first)].name;
        const GradeResults one = onlyStudent(results, folder);
        bool ok = addFile(a.get(), folder + QStringLiteral("/feedback.html"),
                          gradeReportHtml(one).toUtf8());
        QSet<QString> images;
        for (const GradeRow &row : one.rows)
            for (const QString &image : rowImages(one, row))
                if (!image.isEmpty() && !images.contains(image)) {
                    images.insert(image);
                    QFile f(out + image);
                    if (f.open(QIODevice::ReadOnly))
                        ok = ok && addFile(a.get(), folder + QLatin1Char('/') + image, f.readAll());
                }
        if (!ok)
            return fail(CoursePlatformWords::tr("%1: cannot write: %2")
                            .arg(zipPath, QString::fromLocal8Bit(archive_error_string(a.get()))));
    }
    return {};
}

} // namespace phonglab::cli
