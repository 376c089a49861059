#include "NormalStudyOutput.h"

#include "SpeedAccuracyChart.h"
#include "bench/BenchResult.h"
#include "mesh/normals/NormalMethodStudy.h"

#include <QCoreApplication>
#include <QDir>
#include <QSaveFile>
#include <QTextStream>

#include <cstdio>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct NormalStudyOutputWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::NormalStudyOutput)
};

namespace {

QString studyCsv(const std::vector<NormalStudyRow> &rows)
{
    QString out = QStringLiteral("tessellation,method,triangles,ms,max_angle_deg,mean_angle_deg\n");
    for (const NormalStudyRow &r : rows)
        out += QStringList{csvField(r.tessellation),
                           r.method,
                           QString::number(r.triangles),
                           QString::number(r.ms, 'g', 17),
                           QString::number(r.maxAngleDeg, 'g', 17),
                           QString::number(r.meanAngleDeg, 'g', 17)}
                   .join(QLatin1Char(','))
            + QLatin1Char('\n');
    return out;
}

void printStudy(const std::vector<NormalStudyRow> &rows)
{
    QTextStream out(stdout);
    out << "\nnormal methods on sphere tessellations (angle to the exact normal at every "
           "corner):\n";
    out << QStringLiteral("%1 %2 %3 %4 %5 %6\n")
               .arg(QStringLiteral("tessellation"), -34)
               .arg(QStringLiteral("method"), -8)
               .arg(QStringLiteral("triangles"), 9)
               .arg(QStringLiteral("ms"), 8)
               .arg(QStringLiteral("max °"), 7)
               .arg(QStringLiteral("mean °"), 7);
    for (const NormalStudyRow &r : rows)
        out << QStringLiteral("%1 %2 %3 %4 %5 %6\n")
                   .arg(r.tessellation.left(34), -34)
                   .arg(r.method, -8)
                   .arg(r.triangles, 9)
                   .arg(r.ms, 8, 'f', 3)
                   .arg(r.maxAngleDeg, 7, 'f', 2)
                   .arg(r.meanAngleDeg, 7, 'f', 3);
    out.flush();
}

} // namespace

Result<> writeNormalStudy(const QString &outDir)
{
    const std::vector<NormalStudyRow> rows = runNormalStudy(31);
    printStudy(rows);
    const QDir dir(outDir);
    QSaveFile csv(dir.filePath(QStringLiteral("normals.csv")));
    if (!csv.open(QIODevice::WriteOnly | QIODevice::Text) || csv.write(studyCsv(rows).toUtf8()) < 0
        || !csv.commit())
        return fail(NormalStudyOutputWords::tr("%1: cannot write: %2")
                        .arg(csv.fileName(), csv.errorString()));
    return writeNormalStudyChart(rows, dir.filePath(QStringLiteral("normals.png")),
                                 dir.filePath(QStringLiteral("normals.svg")));
}

} // namespace phonglab
