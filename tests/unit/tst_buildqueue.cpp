// When the Shaders dock's text is built (BuildQueue): the pause after edits,
// the same text never built twice by an edit, one request waiting while a
// build is on its way, F5's "always" outranking an edit's "new text", and
// everything waiting while there is no GL yet.
#include "ui/shaders/BuildQueue.h"

#include <QSignalSpy>
#include <QTest>

using namespace phonglab;
using Request = BuildQueue::Request;
using Builder = BuildQueue::Builder;
using Decision = BuildQueue::Decision;

class TestBuildQueue : public QObject
{
    Q_OBJECT

private slots:
    void editsPauseThenOneBuild()
    {
        BuildQueue queue(30);
        QSignalSpy over(&queue, &BuildQueue::pauseOver);
        for (int i = 0; i < 5; ++i) // a burst of typing: one pause, from the last key
            queue.edited();
        QVERIFY(queue.isPausing());
        QVERIFY(over.wait(5000));
        QCOMPARE(over.count(), 1);
        QVERIFY(!queue.isPausing());
        queue.edited();
        queue.stopPause(); // F5 meanwhile
        QVERIFY(!queue.isPausing());
        QVERIFY(!over.wait(100)); // a stopped pause never ends in a build
    }

    void sameTextIsNotBuiltAgainByAnEdit()
    {
        BuildQueue queue(0);
        queue.setLastBuilt("abc");
        QCOMPARE(queue.decide(Request::NewText, "abc", Builder::Ready), Decision::Skip);
        QCOMPARE(queue.decide(Request::Always, "abc", Builder::Ready), Decision::Build);
        QCOMPARE(queue.decide(Request::NewText, "abd", Builder::Ready), Decision::Build);
        QVERIFY(!queue.hasWaiting());
    }

    void oneRequestWaitsWhileBusy()
    {
        BuildQueue queue(0);
        queue.setLastBuilt("a");
        QCOMPARE(queue.decide(Request::NewText, "a", Builder::Busy), Decision::Skip);
        QVERIFY(!queue.hasWaiting());
        QCOMPARE(queue.decide(Request::NewText, "b", Builder::Busy), Decision::Wait);
        QCOMPARE(queue.decide(Request::NewText, "c", Builder::Busy), Decision::Wait);
        QCOMPARE(queue.takeWaiting(), std::optional(Request::NewText));
        QCOMPARE(queue.takeWaiting(), std::nullopt); // handed out once
    }

    void alwaysOutranksNewText()
    {
        BuildQueue queue(0);
        queue.setLastBuilt("a");
        QCOMPARE(queue.decide(Request::Always, "a", Builder::Busy), Decision::Wait);
        QCOMPARE(queue.decide(Request::NewText, "b", Builder::Busy), Decision::Wait);
        QCOMPARE(queue.takeWaiting(), std::optional(Request::Always));
    }

    void everythingWaitsWithoutGl()
    {
        BuildQueue queue(0);
        queue.setLastBuilt("a");
        // Even the text built last: the context it was built in is gone.
        QCOMPARE(queue.decide(Request::NewText, "a", Builder::NoGl), Decision::Wait);
        QVERIFY(queue.hasWaiting());
        queue.forgetWaiting();
        QVERIFY(!queue.hasWaiting());
    }
};

QTEST_GUILESS_MAIN(TestBuildQueue)
#include "tst_buildqueue.moc"
