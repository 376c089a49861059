// What a browser refuses in WebGL 1 and this driver compiles
// (core/program/WebGl1Limits): while and do loops, a loop index started at
// or compared with a uniform. GLSL ES 3.00 and desktop GLSL are not held to
// them; a constant bound with a break at the count passes.
#include "core/program/WebGl1Limits.h"

#include <QTest>

using namespace phonglab;

class TestWebGl1Limits : public QObject
{
    Q_OBJECT

private slots:
    void refused_data()
    {
        QTest::addColumn<QByteArray>("code");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("says");
        QTest::newRow("while") << QByteArray(
            "void main() {\n  int i = 0;\n  while (i < 3) i++;\n}\n")
                               << 3 << 3 << QStringLiteral("This type of loop is not allowed");
        QTest::newRow("do") << QByteArray("void main() { int i = 0; do { i++; } while (i < 3); }")
                            << 1 << 26 << QStringLiteral("no do loops");
        QTest::newRow("a uniform bound")
            << QByteArray("uniform int uNumLights;\nvoid main() {\n  for (int i = 0; i < "
                          "uNumLights; i++) {}\n}\n")
            << 3 << 23 << QStringLiteral("compared with non-constant expression");
        QTest::newRow("a uniform start")
            << QByteArray("uniform int first;\nvoid main() { for (int i = first; i < 4; i++) {} }")
            << 2 << 28 << QStringLiteral("initialized with non-constant expression");
    }

    void refused()
    {
        QFETCH(QByteArray, code);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QString, says);
        const std::vector<WebGlRefusal> r = webGl1Refusals(code);
        QCOMPARE(r.size(), std::size_t(1));
        QCOMPARE(r.front().line, line);
        QCOMPARE(r.front().column, column);
        QVERIFY2(r.front().message.contains(says), qPrintable(r.front().message));
    }

    void allowed()
    {
        // WebGL 1's own way: a constant bound and a break at the count.
        QVERIFY(webGl1Refusals("uniform int n;\nconst int MAX = 4;\nvoid main() {\n  for (int i "
                               "= 0; i < MAX; i++) { if (i >= n) break; }\n}\n")
                    .empty());
        // GLSL ES 3.00 and desktop GLSL have no such limits.
        QVERIFY(webGl1Refusals("#version 300 es\nuniform int n;\nvoid main() { for (int i = 0; "
                               "i < n; i++) {} while (n > 0) {} }")
                    .empty());
        QVERIFY(webGl1Refusals("#version 330 core\nvoid main() { int i = 0; while (i < 3) i++; }")
                    .empty());
    }
};

QTEST_GUILESS_MAIN(TestWebGl1Limits)
#include "tst_webgl1limits.moc"
