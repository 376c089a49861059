#include "core/support/FrameLedger.h"

#include <QTest>

using namespace phonglab;

// The view's frame book without a window: what is counted, when frames are
// held after a slow one, and what lets them go again.
class TestFrameLedger : public QObject
{
    Q_OBJECT

private slots:
    void countsWhatIsDrawnAndWhoDrewIt()
    {
        FrameLedger ledger;
        QVERIFY(ledger.mayDraw());
        QVERIFY(!ledger.book(0, 4.0));
        QVERIFY(!ledger.book(16'000'000, 6.0, /*fromLoan=*/true));
        const FrameStats stats = ledger.stats();
        QCOMPARE(stats.rendered, 2);
        QCOMPARE(stats.fromLoans, 1);
        QCOMPARE(stats.held, false);
        QCOMPARE(stats.refused, 0);
        QCOMPARE(ledger.times().meanMs(), 5.0);
    }

    // A frame at the limit is drawn again; one past it is not, and the
    // frames asked for meanwhile are refused and counted.
    void holdsAfterAFrameOverTheLimitOnly()
    {
        FrameLedger ledger;
        QVERIFY(!ledger.book(0, kHoldFramesAfterMs));
        QVERIFY(!ledger.isHeld());
        QVERIFY(ledger.book(1, kHoldFramesAfterMs + 0.5));
        QVERIFY(ledger.isHeld());
        QVERIFY(!ledger.mayDraw());
        QVERIFY(!ledger.mayDraw());
        QCOMPARE(ledger.stats().refused, 2);
        QCOMPARE(ledger.stats().held, true);
        // A second slow frame (one drawn elsewhere, booked late) does not
        // say "held" twice.
        QVERIFY(!ledger.book(2, 900.0));
    }

    void userActionResumesOnce()
    {
        FrameLedger ledger;
        QVERIFY(!ledger.resume()); // nothing held: no frame to ask for
        ledger.book(0, 400.0);
        QVERIFY(ledger.resume());
        QVERIFY(!ledger.isHeld());
        QVERIFY(ledger.mayDraw());
        QVERIFY(!ledger.resume());
    }

    // A new scene or program is drawn once even while held; its frame may
    // hold the view again.
    void releaseLetsOneFrameThrough()
    {
        FrameLedger ledger;
        ledger.book(0, 300.0);
        ledger.releaseHold();
        QVERIFY(ledger.mayDraw());
        QVERIFY(ledger.book(1, 300.0));
        QVERIFY(!ledger.mayDraw());
        QCOMPARE(ledger.stats().refused, 1);
        QCOMPARE(ledger.stats().rendered, 2);
    }
};

QTEST_APPLESS_MAIN(TestFrameLedger)
#include "tst_frameledger.moc"
