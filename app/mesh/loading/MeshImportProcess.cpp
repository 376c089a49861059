#include "MeshImportProcess.h"
#include "core/support/PhonglabExecutable.h"

#include "core/support/Language.h"

#include "MeshCache.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryFile>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstring>
#include <new>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshImportProcessWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshImportProcess)
};

namespace {

constexpr int kPollMs = 20; // how soon Cancel and the wall clock are noticed
constexpr qint64 kMiB = 1024 * 1024;

QString signalName(int signal)
{
    const char *abbrev = sigabbrev_np(signal);
    return abbrev ? QStringLiteral("SIG") + QString::fromLatin1(abbrev) : QStringLiteral("unknown");
}

QStringList childArguments(const QString &path, const NormalOptions &normals,
                           const QString &entryFile, const MeshImportLimits &limits)
{
    QStringList args{QStringLiteral("__import-mesh"), QStringLiteral("--normals"),
                     normalMethodName(normals.method)};
    if (normals.creaseAngleDeg)
        args << QStringLiteral("--crease") << QString::number(*normals.creaseAngleDeg, 'g', 17);
    args << QStringLiteral("--out") << entryFile << QStringLiteral("--address-space-mb")
         << QString::number(limits.addressSpaceBytes / kMiB) << QStringLiteral("--cpu-seconds")
         << QString::number(limits.cpuSeconds)
         // Its warnings and errors reach the user: in the parent's language.
         << QStringLiteral("--lang") << currentLanguage() << QStringLiteral("--") << path;
    return args;
}

// What the child said on stdout: the latest progress and its error line.
struct ChildReport {
    double progress = 0.0;
    QString error;
    bool outOfMemory = false;

    void read(QProcess &child)
    {
        while (child.canReadLine()) {
            const QString line = QString::fromUtf8(child.readLine()).trimmed();
            if (line.startsWith(QLatin1String("progress ")))
                progress = std::clamp(line.mid(9).toDouble(), progress, 1.0);
            else if (line.startsWith(QLatin1String("error ")))
                error = line.mid(6);
            else if (line == QLatin1String("out-of-memory"))
                outOfMemory = true;
        }
    }
};

QString failureMessage(const QProcess &child, const ChildReport &report,
                       const MeshImportLimits &limits)
{
    if (child.exitStatus() == QProcess::CrashExit) {
        const int signal = child.exitCode(); // Qt reports the terminating signal here
        if (signal == SIGXCPU)
            return MeshImportProcessWords::tr(
                       "the reader used up its %1 s of CPU time and was stopped")
                .arg(limits.cpuSeconds);
        return MeshImportProcessWords::tr("the reader crashed with signal %1 (%2)")
            .arg(signal)
            .arg(signalName(signal));
    }
    if (report.outOfMemory || child.exitCode() == kImportExitOutOfMemory)
        return MeshImportProcessWords::tr("the reader ran out of memory (limit %1 MB)")
            .arg(limits.addressSpaceBytes / kMiB);
    if (!report.error.isEmpty())
        return report.error;
    return MeshImportProcessWords::tr("the reader exited with status %1 without a result")
        .arg(child.exitCode());
}

[[noreturn]] void outOfMemory()
{
    // No allocation from here on: say it with write(2) and leave.
    static const char line[] = "out-of-memory\n";
    [[maybe_unused]] const ssize_t n = ::write(STDOUT_FILENO, line, sizeof line - 1);
    ::_exit(kImportExitOutOfMemory);
}

void applyLimits(const MeshImportLimits &limits)
{
    // The child must not outlive the thread that waits for it (app killed).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
#if !defined(__SANITIZE_ADDRESS__)
    if (limits.addressSpaceBytes > 0) {
        const rlimit as{rlim_t(limits.addressSpaceBytes), rlim_t(limits.addressSpaceBytes)};
        ::setrlimit(RLIMIT_AS, &as);
    }
#endif
    if (limits.cpuSeconds > 0) {
        // SIGXCPU at the soft limit; the hard one a little later is SIGKILL.
        const rlimit cpu{rlim_t(limits.cpuSeconds), rlim_t(limits.cpuSeconds) + 5};
        ::setrlimit(RLIMIT_CPU, &cpu);
    }
    std::set_new_handler(outOfMemory);
}

// PHONGLAB_IMPORT_FAULT makes the child misbehave on purpose, so tests can
// check every way a reader can fail without shipping a file that crashes it.
void injectFault()
{
    const QByteArray fault = qgetenv("PHONGLAB_IMPORT_FAULT");
    if (fault == "hang") {
        for (;;)
            ::pause();
    } else if (fault == "crash") {
        // The default action, even where a sanitizer has its own handler
        // (which would report and exit with status 1 instead).
        std::signal(SIGSEGV, SIG_DFL);
        std::raise(SIGSEGV);
    } else if (fault == "oom") {
        for (;;) {
            char *block = new char[64 * kMiB];
            std::memset(block, 1, 64 * kMiB); // touched: the pages count
        }
    } else if (fault == "spin") {
        std::atomic<unsigned long> spins = 0;
        for (;;)
            spins.fetch_add(1, std::memory_order_relaxed);
    }
}

QString temporaryEntryFile()
{
    // Beside the cache, so adopting the answer is a rename.
    const QString folder = MeshCache::enabled() && QDir().mkpath(MeshCache::directory())
        ? MeshCache::directory()
        : QDir::tempPath();
    QTemporaryFile reserve(folder + QStringLiteral("/import-XXXXXX.phmc"));
    reserve.setAutoRemove(false);
    if (!reserve.open())
        return {};
    return reserve.fileName();
}

// A looping reader can log megabytes a second (OpenMesh's does): its
// stderr goes nowhere unless asked for. Our own errors come on stdout.
void routeChildStderr(QProcess &child)
{
    if (qEnvironmentVariableIsSet("PHONGLAB_IMPORT_STDERR"))
        child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    else
        child.setStandardErrorFile(QProcess::nullDevice());
}

// Waits for the child to exit, passing on its progress. Returns why it was
// killed instead (cancelled, or past the wall clock); empty when it exited.
QString waitForChild(QProcess &child, ChildReport &report, const MeshImportLimits &limits,
                     const QString &path, const LoadProgress &progress)
{
    QElapsedTimer clock;
    clock.start();
    QString stopped;
    while (!child.waitForFinished(kPollMs)) {
        report.read(child);
        if (progress && !progress(report.progress)) {
            stopped = QStringLiteral("cancelled");
        } else if (clock.elapsed() > limits.wallClockMs) {
            stopped = MeshImportProcessWords::tr(
                          "%1: the reader stopped answering after %2 s and was stopped; "
                          "the file is probably malformed")
                          .arg(path)
                          .arg(sentenceNumber(limits.wallClockMs / 1000.0, 'g', 3));
        }
        if (!stopped.isEmpty()) {
            child.kill();
            child.waitForFinished(-1);
            return stopped;
        }
    }
    return {};
}

std::optional<MeshLoadResult> readEntryFile(const QString &entryFile)
{
    QFile entry(entryFile);
    std::optional<MeshLoadResult> answer;
    if (entry.open(QIODevice::ReadOnly))
        answer = MeshCache::decode(entry, std::nullopt);
    entry.close();
    return answer;
}

} // namespace

MeshImportLimits MeshImportLimits::forFile(qint64 fileBytes)
{
    MeshImportLimits limits;
    const qint64 mb = std::max<qint64>(0, fileBytes) / kMiB;
    limits.wallClockMs = int(std::min<qint64>(30'000 + mb * 500, 3'600'000));
    limits.addressSpaceBytes = 2048 * kMiB + 40 * std::max<qint64>(0, fileBytes);
    bool ok = false;
    const double seconds = qEnvironmentVariable("PHONGLAB_IMPORT_TIMEOUT_S").toDouble(&ok);
    if (ok && seconds > 0 && std::isfinite(seconds))
        limits.wallClockMs = int(std::min(seconds * 1000.0, 86'400'000.0));
    const qint64 memoryMb = qEnvironmentVariable("PHONGLAB_IMPORT_MEMORY_MB").toLongLong(&ok);
    if (ok && memoryMb > 0)
        limits.addressSpaceBytes = memoryMb * kMiB;
    // CPU time never decides before the wall clock does, unless the child
    // runs on more cores than one.
    limits.cpuSeconds = limits.wallClockMs / 1000 + 10;
    return limits;
}

MeshLoadResult importMeshIsolated(const QString &path, const NormalOptions &normals,
                                  const LoadProgress &progress)
{
    MeshLoadResult result;
    const auto fail = [&](const QString &why) {
        result.error = QStringLiteral("%1: %2").arg(path, why);
        return result;
    };
    const QString executable = phonglabExecutable();
    if (executable.isEmpty())
        return fail(MeshImportProcessWords::tr(
            "cannot find the phonglab executable that imports meshes (set PHONGLAB_EXE)"));
    const QString entryFile = temporaryEntryFile();
    if (entryFile.isEmpty())
        return fail(MeshImportProcessWords::tr("cannot create a temporary file for the import"));
    const MeshImportLimits limits = MeshImportLimits::forFile(QFileInfo(path).size());

    QProcess child;
    routeChildStderr(child);
    child.start(executable, childArguments(path, normals, entryFile, limits), QIODevice::ReadOnly);
    if (!child.waitForStarted(10'000)) {
        QFile::remove(entryFile);
        return fail(MeshImportProcessWords::tr("cannot start the import process %1: %2")
                        .arg(executable, child.errorString()));
    }
    ChildReport report;
    const QString stopped = waitForChild(child, report, limits, path, progress);
    if (!stopped.isEmpty()) {
        QFile::remove(entryFile);
        result.error = stopped;
        return result;
    }
    report.read(child);
    if (child.exitStatus() != QProcess::NormalExit || child.exitCode() != 0) {
        QFile::remove(entryFile);
        const QString why = failureMessage(child, report, limits);
        // A load error already names the file, as importMeshFile() says it.
        result.error = why.startsWith(path) ? why : QStringLiteral("%1: %2").arg(path, why);
        return result;
    }
    std::optional<MeshLoadResult> answer = readEntryFile(entryFile);
    if (!answer) {
        QFile::remove(entryFile);
        return fail(MeshImportProcessWords::tr("the import process gave no readable result"));
    }
    MeshCache::adopt(entryFile, path, normals);
    answer->stats.creaseAngleDeg = normals.creaseAngleDeg;
    if (progress)
        progress(1.0);
    return std::move(*answer);
}

int runMeshImportChild(const QString &path, const NormalOptions &normals, const QString &entryFile,
                       const MeshImportLimits &limits)
{
    applyLimits(limits);
    injectFault();
    int reported = -1;
    const LoadProgress report = [&reported](double f) {
        const int percent = int(std::clamp(f, 0.0, 1.0) * 100.0);
        if (percent != reported) {
            reported = percent;
            std::printf("progress %.2f\n", percent / 100.0);
            std::fflush(stdout);
        }
        return true; // the parent cancels by killing this process
    };
    const MeshLoadResult result = importMeshFile(path, normals, report);
    if (!result.ok()) {
        std::printf("error %s\n", result.error.simplified().toUtf8().constData());
        std::fflush(stdout);
        return 1;
    }
    // A plain write, not QSaveFile: the parent reads the entry only after a
    // clean exit, and QSaveFile's fsync of tens of megabytes bought nothing
    // (a cache entry cut short by a power cut fails decode() and is dropped).
    QFile out(entryFile);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate)
        || !MeshCache::encode(out, MeshCache::sourceKey(path, normals), result) || !out.flush()) {
        std::printf("error %s\n",
                    MeshImportProcessWords::tr("cannot write the result to %1")
                        .arg(entryFile)
                        .toUtf8()
                        .constData());
        return 1;
    }
    return 0;
}

} // namespace phonglab
