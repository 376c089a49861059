// Archives as students and course platforms hand them in (
// cli/grade/SubmissionArchive, cli/grade/ClassStaging): read with libarchive; every
// hostile form refused whole with its reason, nothing written outside the
// folder it is unpacked in; names in UTF-8 and CP437; Moodle's two layouts.
#include "cli/grade/ClassStaging.h"
#include "cli/grade/SubmissionArchive.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <archive.h>
#include <archive_entry.h>

using namespace phonglab;
using namespace phonglab::cli;

namespace {

quint32 crc32Of(const QByteArray &data)
{
    quint32 crc = 0xFFFFFFFFu;
    for (const char c : data) {
        crc ^= static_cast<unsigned char>(c);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void le16(QByteArray &out, quint32 v)
{
    out += char(v & 0xFF);
    out += char((v >> 8) & 0xFF);
}

void le32(QByteArray &out, quint32 v)
{
    le16(out, v & 0xFFFF);
    le16(out, v >> 16);
}

// A zip written byte by byte (stored entries): any name, the UTF-8 flag or
// not, any Unix mode (a link is mode 0120777 with the target as data).
struct ZipEntry {
    QByteArray name;
    QByteArray data;
    bool utf8 = false;
    quint32 mode = 0100644;
};

QByteArray makeZip(const std::vector<ZipEntry> &entries)
{
    QByteArray out, central;
    for (const ZipEntry &e : entries) {
        const quint32 offset = quint32(out.size());
        const quint32 crc = crc32Of(e.data);
        const quint32 flags = e.utf8 ? 0x800 : 0;
        le32(out, 0x04034b50);
        le16(out, 20);
        le16(out, flags);
        le16(out, 0); // stored
        le32(out, 0); // time, date
        le32(out, crc);
        le32(out, quint32(e.data.size()));
        le32(out, quint32(e.data.size()));
        le16(out, quint32(e.name.size()));
        le16(out, 0);
        out += e.name + e.data;
        le32(central, 0x02014b50);
        le16(central, 0x0314); // made by Unix
        le16(central, 20);
        le16(central, flags);
        le16(central, 0);
        le32(central, 0);
        le32(central, crc);
        le32(central, quint32(e.data.size()));
        le32(central, quint32(e.data.size()));
        le16(central, quint32(e.name.size()));
        le16(central, 0);
        le16(central, 0);
        le16(central, 0);
        le16(central, 0);
        le32(central, e.mode << 16);
        le32(central, offset);
        central += e.name;
    }
    const quint32 centralAt = quint32(out.size());
    out += central;
    le32(out, 0x06054b50);
    le16(out, 0);
    le16(out, 0);
    le16(out, quint32(entries.size()));
    le16(out, quint32(entries.size()));
    le32(out, quint32(central.size()));
    le32(out, centralAt);
    le16(out, 0);
    return out;
}

// A deflated zip or a tar.gz through libarchive's own writer.
struct WrittenEntry {
    WrittenEntry(QByteArray n, QByteArray d, mode_t t = AE_IFREG, QByteArray l = {}, bool h = false)
        : name(std::move(n))
        , data(std::move(d))
        , type(t)
        , link(std::move(l))
        , hard(h)
    {
    }
    QByteArray name;
    QByteArray data;
    mode_t type = AE_IFREG;
    QByteArray link; // a symbolic or hard link's target
    bool hard = false;
};

void writeArchive(const QString &path, const std::vector<WrittenEntry> &entries, bool zip)
{
    archive *a = archive_write_new();
    if (zip) {
        archive_write_set_format_zip(a);
    } else {
        archive_write_set_format_pax_restricted(a);
        archive_write_add_filter_gzip(a);
    }
    QVERIFY(archive_write_open_filename(a, QFile::encodeName(path).constData()) == ARCHIVE_OK);
    for (const WrittenEntry &e : entries) {
        archive_entry *entry = archive_entry_new();
        archive_entry_set_pathname(entry, e.name.constData());
        archive_entry_set_filetype(entry, e.type);
        archive_entry_set_perm(entry, 0644);
        if (!e.link.isEmpty()) {
            if (e.hard)
                archive_entry_set_hardlink(entry, e.link.constData());
            else
                archive_entry_set_symlink(entry, e.link.constData());
        }
        archive_entry_set_size(entry, e.type == AE_IFREG && !e.hard ? e.data.size() : 0);
        archive_write_header(a, entry);
        if (e.type == AE_IFREG && !e.hard)
            archive_write_data(a, e.data.constData(), std::size_t(e.data.size()));
        archive_entry_free(entry);
    }
    archive_write_close(a);
    archive_write_free(a);
}

void writeBytes(const QString &path, const QByteArray &bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

// Every file under `dir`, relative to it.
QStringList filesUnder(const QString &dir)
{
    QStringList files;
    QDirIterator it(dir, QDir::AllEntries | QDir::System | QDir::Hidden | QDir::NoDotAndDotDot,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        files << QDir(dir).relativeFilePath(it.next());
    files.sort();
    return files;
}

} // namespace

class TestSubmissionArchives : public QObject
{
    Q_OBJECT

private slots:
    void hostileArchivesAreRefusedAndWriteNothing_data()
    {
        QTest::addColumn<QByteArray>("zip");
        QTest::addColumn<QString>("reason");
        QTest::newRow("dot-dot") << makeZip({{"ok.frag", "void main(){}"}, {"../evil.txt", "x"}})
                                 << QStringLiteral("leaves the folder");
        QTest::newRow("dot-dot inside")
            << makeZip({{"a/../../evil.txt", "x"}}) << QStringLiteral("leaves the folder");
        QTest::newRow("absolute") << makeZip({{"/tmp/phonglab-evil.txt", "x"}})
                                  << QStringLiteral("leaves the folder");
        QTest::newRow("backslashes")
            << makeZip({{"..\\evil.txt", "x"}}) << QStringLiteral("leaves the folder");
        QTest::newRow("symbolic link")
            << makeZip({{"phong.frag", "/etc/passwd", false, 0120777}}) << QStringLiteral("a link");
        QTest::newRow("corrupt") << makeZip({{"a.frag", "void main(){}"}}).left(40)
                                 << QStringLiteral("damaged");
    }

    void hostileArchivesAreRefusedAndWriteNothing()
    {
        QFETCH(QByteArray, zip);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        const QString archive = dir.filePath(QStringLiteral("hand-in.zip"));
        writeBytes(archive, zip);
        const QString into = dir.filePath(QStringLiteral("work/into"));
        const Result<UnpackedArchive> done = unpackArchive(archive, into);
        QVERIFY(!done);
        QVERIFY2(done.error().contains(reason), qPrintable(done.error()));
        QVERIFY2(done.error().startsWith(QStringLiteral("hand-in.zip: ")),
                 qPrintable(done.error()));
        // Nothing beside the archive, nothing in its folder, nothing in /tmp.
        const QStringList left = filesUnder(dir.path());
        QVERIFY2(left == QStringList{QStringLiteral("hand-in.zip")}
                     || left
                         == (QStringList{QStringLiteral("hand-in.zip"), QStringLiteral("work")}),
                 qPrintable(left.join(QLatin1Char(' '))));
        QVERIFY(!QFile::exists(QStringLiteral("/tmp/phonglab-evil.txt")));
    }

    void linksAndOversizeInTar()
    {
        QTemporaryDir dir;
        const QString tar = dir.filePath(QStringLiteral("class.tar.gz"));
        writeArchive(tar,
                     {{"a/phong.frag", "void main(){}"}, {"a/link", {}, AE_IFLNK, "/etc/passwd"}},
                     false);
        Result<UnpackedArchive> done = unpackArchive(tar, dir.filePath(QStringLiteral("x")));
        QVERIFY(!done && done.error().contains(QStringLiteral("a link")));
        writeArchive(
            tar,
            {{"a/phong.frag", "void main(){}"}, {"a/hard", {}, AE_IFREG, "a/phong.frag", true}},
            false);
        done = unpackArchive(tar, dir.filePath(QStringLiteral("x")));
        QVERIFY(!done && done.error().contains(QStringLiteral("a link")));
        // Over the byte limit (a small one here; the default is 1 GiB).
        QByteArray noise(3 << 20, 0);
        for (qsizetype i = 0; i < noise.size(); ++i)
            noise[i] = char((i * 2654435761u) >> 13);
        writeArchive(tar, {{"big.bin", noise}}, false);
        ArchiveLimits small;
        small.maxBytes = 1 << 20;
        done = unpackArchive(tar, dir.filePath(QStringLiteral("x")), small);
        QVERIFY(!done && done.error().contains(QStringLiteral("MiB unpacked")));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("x"))));
        QCOMPARE(ArchiveLimits().maxBytes, qint64(1) << 30);
        QCOMPARE(ArchiveLimits().maxEntries, qint64(10000));
    }

    void tooManyEntries()
    {
        std::vector<ZipEntry> many;
        for (int i = 0; i <= 10000; ++i)
            many.push_back({QByteArray("f") + QByteArray::number(i), "x"});
        QTemporaryDir dir;
        writeBytes(dir.filePath(QStringLiteral("many.zip")), makeZip(many));
        const Result<UnpackedArchive> done = unpackArchive(dir.filePath(QStringLiteral("many.zip")),
                                                           dir.filePath(QStringLiteral("x")));
        QVERIFY(!done && done.error().contains(QStringLiteral("10000 entries")));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("x"))));
    }

    void zipBomb()
    {
        QTemporaryDir dir;
        const QString bomb = dir.filePath(QStringLiteral("bomb.zip"));
        writeArchive(bomb, {{"zeros.bin", QByteArray(80 << 20, 0)}}, true);
        QVERIFY(QFileInfo(bomb).size() < (1 << 20));
        const Result<UnpackedArchive> done = unpackArchive(bomb, dir.filePath(QStringLiteral("x")));
        QVERIFY2(!done && done.error().contains(QStringLiteral("zip bomb")),
                 qPrintable(done.error()));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("x"))));
    }

    void namesInUtf8AndCp437()
    {
        QTemporaryDir dir;
        // "Jürgen" in CP437 (ü = 0x81) without the UTF-8 flag, "Zoë" with it.
        writeBytes(dir.filePath(QStringLiteral("names.zip")),
                   makeZip({{QByteArray("J\x81rgen/phong.frag"), "void main(){}"},
                            {QByteArray("Zo\xc3\xab/phong.frag"), "void main(){}", true}}));
        const Result<UnpackedArchive> done = unpackArchive(
            dir.filePath(QStringLiteral("names.zip")), dir.filePath(QStringLiteral("x")));
        QVERIFY2(done, qPrintable(done.error()));
        QCOMPARE(filesUnder(dir.filePath(QStringLiteral("x"))),
                 (QStringList{QStringLiteral("Jürgen"), QStringLiteral("Jürgen/phong.frag"),
                              QStringLiteral("Zoë"), QStringLiteral("Zoë/phong.frag")}));
    }

    void moodleLayoutsAndNestedArchives()
    {
        QTemporaryDir dir;
        // One student's own zip, and one with a hostile zip inside.
        const QByteArray own = makeZip({{"project/index.html", "<html></html>"}});
        const QByteArray hostile = makeZip({{"../../../escape.txt", "x"}});
        writeBytes(dir.filePath(QStringLiteral("download.zip")),
                   makeZip({{"Anna Beck_1001_assignsubmission_file_/phong.frag", "void main(){}"},
                            {"Anna Beck_1001_assignsubmission_onlinetext_/onlinetext.html", "hi"},
                            {"Ben Cho_1002_assignsubmission_file_index.html", "<html></html>"},
                            {"Ben Cho_1002_assignsubmission_file_main.js", "//"},
                            {"Cem Demir_1003_assignsubmission_file_/hand-in.zip", own},
                            {"Dora Eng_1004_assignsubmission_file_/evil.zip", hostile}}));
        const QString out = dir.filePath(QStringLiteral("out"));
        const StagedClass staged = stageClass(dir.filePath(QStringLiteral("download.zip")), out);
        QVERIFY2(staged.error.isEmpty(), qPrintable(staged.error));
        QVERIFY(staged.root.startsWith(out + QStringLiteral("/unpacked/")));
        QCOMPARE(
            staged.origins.value(QStringLiteral("Ben Cho_1002_assignsubmission_file_")).participant,
            QStringLiteral("1002"));
        QCOMPARE(
            staged.origins.value(QStringLiteral("Anna Beck_1001_assignsubmission_file_")).student,
            QStringLiteral("Anna Beck"));
        const QStringList files = filesUnder(staged.root);
        QVERIFY(files.contains(QStringLiteral("Ben Cho_1002_assignsubmission_file_/index.html")));
        QVERIFY(files.contains(QStringLiteral("Ben Cho_1002_assignsubmission_file_/main.js")));
        QVERIFY(files.contains(QStringLiteral(
            "Cem Demir_1003_assignsubmission_file_/hand-in.zip.unpacked/project/index.html")));
        QVERIFY(staged.refused.value(QStringLiteral("Dora Eng_1004_assignsubmission_file_"))
                    .contains(QStringLiteral("leaves the folder")));
        // Nothing escaped: every file is under the out folder or is the download.
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("escape.txt"))));
        for (const QString &f : filesUnder(dir.path()))
            QVERIFY2(f == QLatin1String("download.zip") || f.startsWith(QLatin1String("out")),
                     qPrintable(f));
    }

    void aTeachersFolderIsNeverWrittenInto()
    {
        QTemporaryDir dir;
        const QString classFolder = dir.filePath(QStringLiteral("class"));
        writeBytes(classFolder + QStringLiteral("/alice/phong.frag"), "void main(){}");
        writeBytes(classFolder + QStringLiteral("/bob/hand-in.zip"),
                   makeZip({{"phong.frag", "void main(){}"}}));
        const QStringList before = filesUnder(classFolder);
        const StagedClass staged = stageClass(classFolder, dir.filePath(QStringLiteral("out")));
        QVERIFY(staged.error.isEmpty());
        QCOMPARE(filesUnder(classFolder), before);
        QVERIFY(
            QFile::exists(staged.root + QStringLiteral("/bob/hand-in.zip.unpacked/phong.frag")));
        // A plain folder with nothing to unpack is read where it is.
        QVERIFY(QFile::remove(classFolder + QStringLiteral("/bob/hand-in.zip")));
        QCOMPARE(stageClass(classFolder, dir.filePath(QStringLiteral("out"))).root,
                 QFileInfo(classFolder).absoluteFilePath());
    }
};

QTEST_GUILESS_MAIN(TestSubmissionArchives)
#include "tst_submissionarchives.moc"
