#include "BenchProcess.h"

#include "core/support/Language.h"
#include "core/support/PhonglabExecutable.h"

#include "core/scene/SceneJson.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QRegularExpression>

namespace phonglab {

namespace {

// Mesh paths made absolute (or ":/..." resources, which the child has too),
// so the temporary scene can live anywhere.
Scene withAbsoluteMeshes(Scene scene)
{
    for (SceneObject &object : scene.objects)
        object.mesh = scene.resolveMeshPath(object.mesh);
    // The shipped methods are measured; the user's own shader files are not.
    scene.vertexShader.clear();
    scene.fragmentShader.clear();
    return scene;
}

QString budgetArgument(const ErrorBudget &budget)
{
    return budget.kind == ErrorBudget::Kind::Psnr ? QStringLiteral("psnr:%1").arg(budget.minPsnr)
                                                  : QString::number(budget.maxError);
}

} // namespace

BenchProcess::BenchProcess(QObject *parent)
    : QObject(parent)
{
}

BenchProcess::~BenchProcess()
{
    if (m_process) {
        m_process->disconnect(this);
        m_process->kill();
        m_process->waitForFinished(2000);
    }
}

std::vector<double> BenchProcess::detailLevels()
{
    return {1.0, 1.0 / 2, 1.0 / 4, 1.0 / 8, 1.0 / 16, 1.0 / 32, 1.0 / 64};
}

QString BenchProcess::executable() const
{
    return phonglabExecutable();
}

bool BenchProcess::isRunning() const
{
    return m_process != nullptr;
}

Result<> BenchProcess::start(const Scene &scene, const QSize &size, const ErrorBudget &budget)
{
    if (m_process)
        return fail(tr("a measurement is already running"));
    m_dir = std::make_unique<QTemporaryDir>();
    if (!m_dir->isValid())
        return fail(tr("no temporary folder for the measurement: %1").arg(m_dir->errorString()));
    const QString scenePath = m_dir->filePath(QStringLiteral("scene.json"));
    if (Result<> saved = saveSceneFile(withAbsoluteMeshes(scene), scenePath); !saved)
        return saved;

    QStringList details;
    for (double d : detailLevels())
        details << QString::number(d, 'g', 17);
    const QStringList arguments{
        QStringLiteral("bench"), QStringLiteral("--scene"), scenePath, QStringLiteral("--lights"),
        QStringLiteral("scene"), QStringLiteral("--details"), details.join(QLatin1Char(',')),
        QStringLiteral("--size"),
        QStringLiteral("%1x%2").arg(std::max(size.width(), 16)).arg(std::max(size.height(), 16)),
        QStringLiteral("--budget"), budgetArgument(budget), QStringLiteral("--out"),
        m_dir->filePath(QStringLiteral("out")),
        // Its progress lines are shown in the dock: in the window's language.
        QStringLiteral("--lang"), currentLanguage()};
    m_process = new QProcess(this);
    m_stderr.clear();
    m_lastErrorLine.clear();
    m_cancelled = false;
    connect(m_process, &QProcess::readyReadStandardError, this, &BenchProcess::readProgress);
    connect(m_process, &QProcess::finished, this, &BenchProcess::processFinished);
    connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart)
            processFinished(-1, QProcess::CrashExit);
    });
    m_process->start(executable(), arguments);
    return {};
}

void BenchProcess::cancel()
{
    if (!m_process)
        return;
    m_cancelled = true;
    m_process->kill(); // finished() follows
}

void BenchProcess::readProgress()
{
    static const QRegularExpression step(QStringLiteral(R"(^\[(\d+)/(\d+)\] (.*)$)"));
    m_stderr += m_process->readAllStandardError();
    qsizetype newline;
    while ((newline = m_stderr.indexOf('\n')) >= 0) {
        const QString line = QString::fromUtf8(m_stderr.left(newline)).trimmed();
        m_stderr.remove(0, newline + 1);
        const auto m = step.match(line);
        if (m.hasMatch())
            emit progress(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3));
        else if (line.startsWith(QLatin1String("phonglab: error: ")))
            m_lastErrorLine = line.mid(17);
    }
}

void BenchProcess::processFinished(int exitCode, QProcess::ExitStatus status)
{
    if (!m_process)
        return;
    readProgress();
    const QString program = m_process->program();
    const QString startError =
        m_process->error() == QProcess::FailedToStart ? m_process->errorString() : QString();
    m_process->deleteLater();
    m_process = nullptr;

    std::vector<BenchRow> rows;
    QString error;
    if (m_cancelled) {
        error = tr("cancelled");
    } else if (!startError.isEmpty()) {
        error = tr("could not run %1: %2").arg(program, startError);
    } else if (status != QProcess::NormalExit || exitCode != 0) {
        error = m_lastErrorLine.isEmpty() ? tr("the measurement stopped (exit %1)").arg(exitCode)
                                          : m_lastErrorLine;
    } else {
        QFile file(m_dir->filePath(QStringLiteral("out/results.csv")));
        if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
            error = tr("the measurement wrote no results: %1").arg(file.errorString());
        else if (Result<std::vector<BenchRow>> read =
                     benchRowsFromCsv(QString::fromUtf8(file.readAll())))
            rows = std::move(*read);
        else
            error = read.error();
    }
    if (!error.isEmpty())
        rows.clear();
    emit finished(rows, error);
}

} // namespace phonglab
