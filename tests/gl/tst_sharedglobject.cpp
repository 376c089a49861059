// SharedGlObject frees a program exactly once, through a context of the
// program's own share group, and never through another group's context,
// where the same number names another program.
#include "render/gl/GlFormat.h"
#include "render/gl/SharedGlObject.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QTest>
#include <memory>

using namespace phonglab;

class TestSharedGlObject : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanupTestCase();
    void freesWhenItGoes();
    void movedFromFreesNothing();
    void anyContextOfTheGroupFrees();
    void anotherGroupsObjectOfTheSameNameSurvives();
    void withoutAContextTheGroupKeepsIt();

private:
    std::unique_ptr<QOpenGLContext> makeContext(QOpenGLContext *shareWith);
    bool isProgramIn(QOpenGLContext *context, GLuint id);
    GlProgram newProgram() { return GlProgram(m_first->functions()->glCreateProgram()); }

    QOffscreenSurface m_surface;
    std::unique_ptr<QOpenGLContext> m_first;
    std::unique_ptr<QOpenGLContext> m_sharing; // same group as m_first
    std::unique_ptr<QOpenGLContext> m_other;   // a group of its own
};

std::unique_ptr<QOpenGLContext> TestSharedGlObject::makeContext(QOpenGLContext *shareWith)
{
    auto context = std::make_unique<QOpenGLContext>();
    context->setFormat(phonglabSurfaceFormat(0));
    context->setShareContext(shareWith);
    return context->create() ? std::move(context) : nullptr;
}

bool TestSharedGlObject::isProgramIn(QOpenGLContext *context, GLuint id)
{
    QOpenGLContext *before = QOpenGLContext::currentContext();
    context->makeCurrent(&m_surface);
    const bool is = context->functions()->glIsProgram(id);
    if (before)
        before->makeCurrent(&m_surface);
    else
        context->doneCurrent();
    return is;
}

void TestSharedGlObject::initTestCase()
{
    m_surface.setFormat(phonglabSurfaceFormat(0));
    m_surface.create();
    QVERIFY(m_surface.isValid());
    m_first = makeContext(nullptr);
    QVERIFY(m_first);
    m_sharing = makeContext(m_first.get());
    QVERIFY(m_sharing && QOpenGLContext::areSharing(m_first.get(), m_sharing.get()));
    m_other = makeContext(nullptr);
    QVERIFY(m_other && !QOpenGLContext::areSharing(m_first.get(), m_other.get()));
}

void TestSharedGlObject::init()
{
    QVERIFY(m_first->makeCurrent(&m_surface));
}

void TestSharedGlObject::cleanupTestCase()
{
    if (QOpenGLContext *current = QOpenGLContext::currentContext())
        current->doneCurrent();
}

void TestSharedGlObject::freesWhenItGoes()
{
    GLuint id = 0;
    {
        const GlProgram program = newProgram();
        id = program.id();
        QVERIFY(id != 0);
        QVERIFY(m_first->functions()->glIsProgram(id));
    }
    QVERIFY(!m_first->functions()->glIsProgram(id));
}

void TestSharedGlObject::movedFromFreesNothing()
{
    GlProgram kept;
    GLuint id = 0;
    {
        GlProgram made = newProgram();
        id = made.id();
        kept = std::move(made);
        QVERIFY(!made);
    }
    QVERIFY(m_first->functions()->glIsProgram(id));
    QCOMPARE(kept.id(), id);
    kept.reset();
    QVERIFY(!m_first->functions()->glIsProgram(id));
}

void TestSharedGlObject::anyContextOfTheGroupFrees()
{
    GlProgram program = newProgram();
    const GLuint id = program.id();
    QVERIFY(m_sharing->makeCurrent(&m_surface));
    program.reset(); // what the build thread does with a program nobody wants
    QVERIFY(!m_sharing->functions()->glIsProgram(id));
    QVERIFY(!isProgramIn(m_first.get(), id));
}

void TestSharedGlObject::anotherGroupsObjectOfTheSameNameSurvives()
{
    GlProgram program = newProgram();
    const GLuint id = program.id();
    // Programs in the other group until one has the same number.
    QVERIFY(m_other->makeCurrent(&m_surface));
    std::vector<GlProgram> others;
    while (others.size() <= id && (others.empty() || others.back().id() < id))
        others.emplace_back(m_other->functions()->glCreateProgram());
    QVERIFY2(!others.empty() && others.back().id() == id,
             "the other group never gave out the same number");

    program.reset(); // with the other group's context current: must not touch its program
    QVERIFY(m_other->functions()->glIsProgram(id));
    QVERIFY(isProgramIn(m_first.get(), id)); // left to its own group
    others.clear();
    QVERIFY(m_first->makeCurrent(&m_surface));
    m_first->functions()->glDeleteProgram(id);
}

void TestSharedGlObject::withoutAContextTheGroupKeepsIt()
{
    GlProgram program = newProgram();
    const GLuint id = program.id();
    m_first->doneCurrent();
    program.reset(); // no context: nothing to free it with, and no crash
    QVERIFY(!program);
    QVERIFY(isProgramIn(m_first.get(), id));
    QVERIFY(m_first->makeCurrent(&m_surface));
    m_first->functions()->glDeleteProgram(id);
}

QTEST_MAIN(TestSharedGlObject)
#include "tst_sharedglobject.moc"
