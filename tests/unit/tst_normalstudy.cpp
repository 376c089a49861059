// The normal-method study: angular error against the exact sphere normal,
// per method, on regular and irregular tessellations.
#include "mesh/normals/NormalMethodStudy.h"

#include <QTest>

#include <cmath>

using namespace phonglab;

class TestNormalStudy : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void everyRowIsFinite();
    void angleBeatsAverageOnIrregularSpheres();
    void flatIsClearlyWorst();

private:
    const NormalStudyRow &row(const QString &tessellationStart, const QString &method) const;
    std::vector<NormalStudyRow> m_rows;
};

void TestNormalStudy::initTestCase()
{
    m_rows = runNormalStudy(3);
    for (const NormalStudyRow &r : m_rows)
        qInfo("%-40s %-8s %7lld tris %8.3f ms  max %7.3f deg  mean %7.4f deg",
              qPrintable(r.tessellation), qPrintable(r.method), r.triangles, r.ms, r.maxAngleDeg,
              r.meanAngleDeg);
    QCOMPARE(m_rows.size(), std::size_t(12)); // 3 tessellations × 4 methods
}

const NormalStudyRow &TestNormalStudy::row(const QString &tessellationStart,
                                           const QString &method) const
{
    for (const NormalStudyRow &r : m_rows)
        if (r.tessellation.startsWith(tessellationStart) && r.method == method)
            return r;
    qFatal("no row %s / %s", qPrintable(tessellationStart), qPrintable(method));
}

void TestNormalStudy::everyRowIsFinite()
{
    for (const NormalStudyRow &r : m_rows) {
        QVERIFY(r.triangles > 1000);
        QVERIFY(std::isfinite(r.ms) && r.ms >= 0.0);
        QVERIFY(std::isfinite(r.maxAngleDeg) && std::isfinite(r.meanAngleDeg));
        QVERIFY(r.meanAngleDeg >= 0.0 && r.meanAngleDeg <= r.maxAngleDeg && r.maxAngleDeg < 90.0);
    }
}

void TestNormalStudy::angleBeatsAverageOnIrregularSpheres()
{
    for (const QString &irregular :
         {QStringLiteral("icosphere"), QStringLiteral("UV sphere 128")}) {
        const double angle = row(irregular, QStringLiteral("angle")).meanAngleDeg;
        const double average = row(irregular, QStringLiteral("average")).meanAngleDeg;
        QVERIFY2(angle <= average,
                 qPrintable(QStringLiteral("%1: angle %2 > average %3")
                                .arg(irregular)
                                .arg(angle)
                                .arg(average)));
    }
}

void TestNormalStudy::flatIsClearlyWorst()
{
    for (const QString &t : {QStringLiteral("UV sphere 64"), QStringLiteral("icosphere"),
                             QStringLiteral("UV sphere 128")}) {
        const double flat = row(t, QStringLiteral("flat")).meanAngleDeg;
        for (const QString &smooth :
             {QStringLiteral("average"), QStringLiteral("area"), QStringLiteral("angle")})
            QVERIFY2(flat > 2.0 * row(t, smooth).meanAngleDeg, qPrintable(t + u' ' + smooth));
    }
}

QTEST_APPLESS_MAIN(TestNormalStudy)
#include "tst_normalstudy.moc"
