#include "core/support/FrameTimeWindow.h"

#include <QTest>

using namespace phonglab;

class TestFrameTimeWindow : public QObject
{
    Q_OBJECT

private slots:
    void emptyIsZero()
    {
        QCOMPARE(FrameTimeWindow().meanMs(), 0.0);
        QCOMPARE(FrameTimeWindow().frames(), 0);
    }

    // A slow first frame (the shader's compilation) leaves the mean once it
    // is more than a second old, where a running average would still carry it.
    void slowFirstFrameLeavesAfterASecond()
    {
        constexpr qint64 kMs = 1'000'000;
        FrameTimeWindow window;
        window.add(0, 60.0);
        for (int i = 1; i <= 60; ++i)
            window.add(i * 16 * kMs, 2.0);
        QCOMPARE(window.frames(), 61); // 960 ms: the first frame still counts
        QVERIFY(window.meanMs() > 2.5);
        window.add(1010 * kMs, 2.0);
        QCOMPARE(window.meanMs(), 2.0);
        QCOMPARE(window.frames(), 61);
    }

    void newestFrameAlwaysCounts()
    {
        FrameTimeWindow window;
        window.add(0, 5.0);
        window.add(10 * FrameTimeWindow::kSpanNs, 7.0);
        QCOMPARE(window.frames(), 1);
        QCOMPARE(window.meanMs(), 7.0);
    }

    void atMostMaxFrames()
    {
        FrameTimeWindow window;
        for (int i = 0; i < 3 * FrameTimeWindow::kMaxFrames; ++i)
            window.add(i, i < 2 * FrameTimeWindow::kMaxFrames ? 100.0 : 1.0);
        QCOMPARE(window.frames(), FrameTimeWindow::kMaxFrames);
        QCOMPARE(window.meanMs(), 1.0);
    }
};

QTEST_APPLESS_MAIN(TestFrameTimeWindow)
#include "tst_frametimewindow.moc"
