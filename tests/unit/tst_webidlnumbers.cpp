// The numbers a page's replay hands to GL: WebIDL's conversions of a
// JavaScript number (core/page/WebIdlNumbers.h), where a C++ cast would be
// undefined behaviour.
#include "core/page/WebIdlNumbers.h"

#include <QtTest>

#include <limits>

using namespace phonglab;

class TestWebIdlNumbers : public QObject
{
    Q_OBJECT

private slots:
    void integersAsEcmaScriptMakesThem_data();
    void integersAsEcmaScriptMakesThem();
    void floatsRoundAndOverflowToInfinity();
};

void TestWebIdlNumbers::integersAsEcmaScriptMakesThem_data()
{
    QTest::addColumn<double>("number");
    QTest::addColumn<qint64>("asLong");
    QTest::addColumn<quint64>("asUnsignedLong");
    const double inf = std::numeric_limits<double>::infinity();
    // What (x | 0) and (x >>> 0) give in a browser's console.
    QTest::newRow("a float uniform's value") << -3.2249 << qint64(-3) << quint64(4294967293u);
    QTest::newRow("positive, truncated") << 7.9 << qint64(7) << quint64(7);
    QTest::newRow("minus zero") << -0.0 << qint64(0) << quint64(0);
    QTest::newRow("2^31") << 2147483648.0 << qint64(-2147483648LL) << quint64(2147483648u);
    QTest::newRow("2^32 + 5") << 4294967301.0 << qint64(5) << quint64(5);
    QTest::newRow("-(2^32) - 1") << -4294967297.0 << qint64(-1) << quint64(4294967295u);
    QTest::newRow("1e300") << 1e300 << qint64(0) << quint64(0);
    QTest::newRow("NaN") << std::numeric_limits<double>::quiet_NaN() << qint64(0) << quint64(0);
    QTest::newRow("infinity") << inf << qint64(0) << quint64(0);
    QTest::newRow("-infinity") << -inf << qint64(0) << quint64(0);
}

void TestWebIdlNumbers::integersAsEcmaScriptMakesThem()
{
    QFETCH(double, number);
    QFETCH(qint64, asLong);
    QFETCH(quint64, asUnsignedLong);
    QCOMPARE(qint64(webIdlLong(number)), asLong);
    QCOMPARE(quint64(webIdlUnsignedLong(number)), asUnsignedLong);
}

void TestWebIdlNumbers::floatsRoundAndOverflowToInfinity()
{
    const float inf = std::numeric_limits<float>::infinity();
    const float max = std::numeric_limits<float>::max();
    QCOMPARE(webIdlFloat(0.1), 0.1f);
    QCOMPARE(webIdlFloat(-3.2249), -3.2249f);
    QCOMPARE(webIdlFloat(double(max)), max);
    // Below half FLT_MAX's last place above it: still FLT_MAX; at it: infinity.
    QCOMPARE(webIdlFloat(0x1.fffffefffffffp+127), max);
    QCOMPARE(webIdlFloat(0x1.ffffffp+127), inf);
    QCOMPARE(webIdlFloat(1e300), inf);
    QCOMPARE(webIdlFloat(-1e300), -inf);
    QVERIFY(std::isnan(webIdlFloat(std::numeric_limits<double>::quiet_NaN())));
}

QTEST_APPLESS_MAIN(TestWebIdlNumbers)
#include "tst_webidlnumbers.moc"
