#include "BenchResult.h"

#include "core/support/Language.h"

#include <QCoreApplication>
#include <QHash>

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct BenchResultWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::BenchResult)
};

namespace {

// Column indices, in benchCsvColumns() order.
enum Column {
    ColScene,
    ColMethod,
    ColDetail,
    ColTriangles,
    ColLights,
    ColSceneLights,
    ColFrameMs,
    ColFrameMsP90,
    ColCpuSubmitMs,
    ColGpuMs,
    ColFrames,
    ColPsnr,
    ColRmse,
    ColMaxError,
    ColSpecPsnr,
    ColSpecRmse,
    ColSpecMaxError,
    ColSpecPixels,
    ColPixelsCompared,
    ColCoverageErrors,
    ColObject, // added later: optional when reading, so older files still read
    ColumnCount
};

const char *const kColumnNames[ColumnCount] = {
    "scene",        "method",         "detail",       "triangles",       "lights",
    "scene_lights", "frame_ms",       "frame_ms_p90", "cpu_submit_ms",   "gpu_ms",
    "frames",       "psnr_db",        "rmse",         "max_error",       "spec_psnr_db",
    "spec_rmse",    "spec_max_error", "spec_pixels",  "pixels_compared", "coverage_errors",
    "object",
};

// Shortest text that reads back as exactly the same double.
QString formatDouble(double v)
{
    if (std::isnan(v))
        return QString();
    if (std::isinf(v))
        return v > 0 ? QStringLiteral("inf") : QStringLiteral("-inf");
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    if (result.ec != std::errc())
        return QString::number(v, 'g', 17);
    return QString::fromLatin1(buffer, int(result.ptr - buffer));
}

} // namespace

QString detailPercent(double detail)
{
    const double percent = detail * 100.0;
    const QLocale locale = sentenceLocale();
    const QString number = std::abs(percent) >= 100 ? locale.toString(percent, 'f', 0)
                                                    : locale.toString(percent, 'g', 3);
    return number + QStringLiteral(" %");
}

QString csvField(const QString &field)
{
    const bool needsQuotes = field.contains(QLatin1Char(',')) || field.contains(QLatin1Char('"'))
        || field.contains(QLatin1Char('\n')) || field.contains(QLatin1Char('\r'))
        || (!field.isEmpty() && (field.front().isSpace() || field.back().isSpace()));
    if (!needsQuotes)
        return field;
    QString quoted = field;
    quoted.replace(QLatin1Char('"'), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

namespace {

// One CSV record and the (1-based) line it starts on.
struct Record {
    int line = 0;
    QStringList fields;
};

// Where splitRecords() has got to in the text.
struct CsvCursor {
    const QString &text;
    qsizetype i = 0;
    int line = 1;
};

// One step inside a quoted field: "" is a quote, a lone " ends the quoting.
// Returns whether the field is still quoted.
bool readQuotedChar(CsvCursor &at, QString &field)
{
    const QString &text = at.text;
    const qsizetype n = text.size();
    const QChar c = text.at(at.i);
    if (c == QLatin1Char('"')) {
        if (at.i + 1 < n && text.at(at.i + 1) == QLatin1Char('"')) {
            field += QLatin1Char('"');
            at.i += 2;
            return true;
        }
        ++at.i;
        return false;
    }
    if (c == QLatin1Char('\n'))
        ++at.line;
    field += c;
    ++at.i;
    return true;
}

// RFC 4180: fields separated by commas, records by \n or \r\n, quoted fields
// may hold commas, quotes ("") and line breaks. Blank lines are skipped.
bool splitRecords(const QString &text, std::vector<Record> *records, int *badLine)
{
    CsvCursor at{text};
    const qsizetype n = text.size();
    while (at.i < n) {
        Record record;
        record.line = at.line;
        QString field;
        bool quoted = false;
        bool recordDone = false;
        bool structure = false; // saw a comma or a quote: not a blank line
        while (at.i < n && !recordDone) {
            if (quoted) {
                quoted = readQuotedChar(at, field);
                continue;
            }
            const QChar c = text.at(at.i);
            if (c == QLatin1Char('"')) {
                if (!field.isEmpty()) { // a quote inside an unquoted field
                    *badLine = at.line;
                    return false;
                }
                quoted = true;
                structure = true;
                ++at.i;
            } else if (c == QLatin1Char(',')) {
                record.fields.append(field);
                field.clear();
                structure = true;
                ++at.i;
            } else if (c == QLatin1Char('\r') || c == QLatin1Char('\n')) {
                if (c == QLatin1Char('\r') && at.i + 1 < n
                    && text.at(at.i + 1) == QLatin1Char('\n'))
                    ++at.i;
                ++at.i;
                ++at.line;
                recordDone = true;
            } else {
                field += c;
                ++at.i;
            }
        }
        if (quoted) { // an opening quote never closed
            *badLine = record.line;
            return false;
        }
        if (!structure && field.trimmed().isEmpty())
            continue;
        record.fields.append(field);
        records->push_back(std::move(record));
    }
    return true;
}

class FieldReader
{
public:
    FieldReader(const QString &source, int line)
        : m_source(source)
        , m_line(line)
    {
    }

    bool readDouble(const QString &column, const QString &text, double *out) const
    {
        const QString t = text.trimmed();
        if (t.isEmpty()) {
            *out = std::numeric_limits<double>::quiet_NaN();
            return true;
        }
        const QString lower = t.toLower();
        if (lower == QLatin1String("inf") || lower == QLatin1String("+inf")
            || lower == QLatin1String("infinity")) {
            *out = std::numeric_limits<double>::infinity();
            return true;
        }
        if (lower == QLatin1String("-inf") || lower == QLatin1String("-infinity")) {
            *out = -std::numeric_limits<double>::infinity();
            return true;
        }
        if (lower == QLatin1String("nan")) {
            *out = std::numeric_limits<double>::quiet_NaN();
            return true;
        }
        const QByteArray bytes = t.toLatin1();
        const char *begin = bytes.constData();
        const char *end = begin + bytes.size();
        if (begin != end && *begin == '+')
            ++begin;
        double value = 0;
        const auto result = std::from_chars(begin, end, value);
        if (result.ec != std::errc() || result.ptr != end || lower.contains(QLatin1String("inf"))
            || lower.contains(QLatin1String("nan"))) {
            fail(column, BenchResultWords::tr("is not a number"), text);
            return false;
        }
        *out = value;
        return true;
    }

    bool readInt64(const QString &column, const QString &text, qint64 *out) const
    {
        bool ok = false;
        const qint64 value = text.trimmed().toLongLong(&ok);
        if (!ok) {
            fail(column, BenchResultWords::tr("is not a whole number"), text);
            return false;
        }
        *out = value;
        return true;
    }

    bool readInt(const QString &column, const QString &text, int *out) const
    {
        qint64 value = 0;
        if (!readInt64(column, text, &value))
            return false;
        if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
            fail(column, BenchResultWords::tr("is out of range"), text);
            return false;
        }
        *out = int(value);
        return true;
    }

    bool readBool(const QString &column, const QString &text, bool *out) const
    {
        const QString t = text.trimmed().toLower();
        if (t == QLatin1String("1") || t == QLatin1String("true")) {
            *out = true;
            return true;
        }
        if (t == QLatin1String("0") || t == QLatin1String("false")) {
            *out = false;
            return true;
        }
        fail(column, BenchResultWords::tr("is not 0 or 1"), text);
        return false;
    }

    QString where() const { return QStringLiteral("%1 line %2").arg(m_source).arg(m_line); }
    // Why the last read failed, located: "<source> line N: <column> ...".
    const QString &error() const { return m_error; }

private:
    void fail(const QString &column, const QString &what, const QString &text) const
    {
        m_error = QStringLiteral("%1: %2 %3: '%4'").arg(where(), column, what, text);
    }

    QString m_source;
    int m_line;
    mutable QString m_error;
};

} // namespace

QStringList benchCsvColumns()
{
    QStringList columns;
    for (const char *name : kColumnNames)
        columns.append(QString::fromLatin1(name));
    return columns;
}

QString benchRowsToCsv(const std::vector<BenchRow> &rows)
{
    QString out = benchCsvColumns().join(QLatin1Char(',')) + QLatin1Char('\n');
    for (const BenchRow &row : rows) {
        const QStringList fields = {
            csvField(row.scene),
            csvField(row.method),
            formatDouble(row.detail),
            QString::number(row.triangles),
            QString::number(row.lights),
            row.sceneLights ? QStringLiteral("1") : QStringLiteral("0"),
            formatDouble(row.frameMs),
            formatDouble(row.frameMsP90),
            formatDouble(row.cpuSubmitMs),
            formatDouble(row.gpuMs),
            QString::number(row.frames),
            formatDouble(row.psnr),
            formatDouble(row.rmse),
            QString::number(row.maxError),
            formatDouble(row.specularPsnr),
            formatDouble(row.specularRmse),
            QString::number(row.specularMaxError),
            QString::number(row.specularPixels),
            QString::number(row.pixelsCompared),
            QString::number(row.coverageErrors),
            csvField(row.object),
        };
        out += fields.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    return out;
}

namespace {

// Per known column, the field it is in (-1: not in the file).
struct ColumnIndex {
    int at[ColumnCount];
};

// Header: find each known column by name; unknown ones are skipped.
Result<ColumnIndex> findColumns(const Record &header, const QString &sourceName)
{
    ColumnIndex index;
    std::fill(std::begin(index.at), std::end(index.at), -1);
    for (int f = 0; f < header.fields.size(); ++f) {
        const QString name = header.fields.at(f).trimmed();
        for (int c = 0; c < ColumnCount; ++c) {
            if (name == QLatin1String(kColumnNames[c])) {
                if (index.at[c] != -1)
                    return fail(BenchResultWords::tr("%1 line %2: column '%3' appears twice")
                                    .arg(sourceName)
                                    .arg(header.line)
                                    .arg(name));
                index.at[c] = f;
            }
        }
    }
    QStringList missing;
    for (int c = 0; c < ColumnCount; ++c)
        if (index.at[c] == -1 && c != ColObject)
            missing.append(QString::fromLatin1(kColumnNames[c]));
    if (!missing.isEmpty())
        return fail((missing.size() == 1 ? BenchResultWords::tr("%1 line %2: missing column %3")
                                         : BenchResultWords::tr("%1 line %2: missing columns %3"))
                        .arg(sourceName)
                        .arg(header.line)
                        .arg(missing.join(QStringLiteral(", "))));
    return index;
}

Result<BenchRow> parseRow(const Record &record, const Record &header, const ColumnIndex &index,
                          const QString &sourceName)
{
    const FieldReader reader(sourceName, record.line);
    if (record.fields.size() != header.fields.size())
        return fail(BenchResultWords::tr("%1: expected %2 fields as in the header, found %3")
                        .arg(reader.where())
                        .arg(header.fields.size())
                        .arg(record.fields.size()));
    auto field = [&](Column c) { return record.fields.at(index.at[c]); };
    auto name = [](Column c) { return QString::fromLatin1(kColumnNames[c]); };

    BenchRow row;
    row.scene = field(ColScene);
    row.method = field(ColMethod).trimmed();
    if (index.at[ColObject] != -1)
        row.object = field(ColObject);
    const bool ok = reader.readDouble(name(ColDetail), field(ColDetail), &row.detail)
        && reader.readInt64(name(ColTriangles), field(ColTriangles), &row.triangles)
        && reader.readInt(name(ColLights), field(ColLights), &row.lights)
        && reader.readBool(name(ColSceneLights), field(ColSceneLights), &row.sceneLights)
        && reader.readDouble(name(ColFrameMs), field(ColFrameMs), &row.frameMs)
        && reader.readDouble(name(ColFrameMsP90), field(ColFrameMsP90), &row.frameMsP90)
        && reader.readDouble(name(ColCpuSubmitMs), field(ColCpuSubmitMs), &row.cpuSubmitMs)
        && reader.readDouble(name(ColGpuMs), field(ColGpuMs), &row.gpuMs)
        && reader.readInt(name(ColFrames), field(ColFrames), &row.frames)
        && reader.readDouble(name(ColPsnr), field(ColPsnr), &row.psnr)
        && reader.readDouble(name(ColRmse), field(ColRmse), &row.rmse)
        && reader.readInt(name(ColMaxError), field(ColMaxError), &row.maxError)
        && reader.readDouble(name(ColSpecPsnr), field(ColSpecPsnr), &row.specularPsnr)
        && reader.readDouble(name(ColSpecRmse), field(ColSpecRmse), &row.specularRmse)
        && reader.readInt(name(ColSpecMaxError), field(ColSpecMaxError), &row.specularMaxError)
        && reader.readInt64(name(ColSpecPixels), field(ColSpecPixels), &row.specularPixels)
        && reader.readInt64(name(ColPixelsCompared), field(ColPixelsCompared), &row.pixelsCompared)
        && reader.readInt64(name(ColCoverageErrors), field(ColCoverageErrors), &row.coverageErrors);
    if (!ok)
        return fail(reader.error());
    if (row.method.isEmpty())
        return fail(BenchResultWords::tr("%1: method is empty").arg(reader.where()));
    return row;
}

} // namespace

Result<std::vector<BenchRow>> benchRowsFromCsv(const QString &text, const QString &sourceName)
{
    QString body = text;
    if (body.startsWith(QChar(0xFEFF)))
        body.remove(0, 1);

    std::vector<Record> records;
    int badLine = 0;
    if (!splitRecords(body, &records, &badLine))
        return fail(
            BenchResultWords::tr("%1 line %2: unbalanced quotes").arg(sourceName).arg(badLine));
    if (records.empty())
        return fail(
            BenchResultWords::tr("%1: empty file, expected a header line starting with '%2'")
                .arg(sourceName, QString::fromLatin1(kColumnNames[0])));

    const Record &header = records.front();
    const Result<ColumnIndex> index = findColumns(header, sourceName);
    if (!index)
        return fail(index.error());

    std::vector<BenchRow> parsed;
    parsed.reserve(records.size() - 1);
    for (size_t r = 1; r < records.size(); ++r) {
        Result<BenchRow> row = parseRow(records[r], header, *index, sourceName);
        if (!row)
            return fail(row.error());
        parsed.push_back(std::move(*row));
    }
    return parsed;
}

} // namespace phonglab
