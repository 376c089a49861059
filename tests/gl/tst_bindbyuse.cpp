// Binding by use never hides a mistake: the shipped Phong pair with every
// uniform binding by use can place renamed to a word that means nothing
// (`q0`, `q1`, ...) is bound with no --bind and still passes, and each
// classic mistake made in it is still named. The names are the only thing
// that differs from gl.tst_checkmistakes' pairs.
#include "CheckScene.h"
#include "RenderCheck.h"
#include "ResultChecks.h"
#include "ShaderMutations.h"
#include "core/check/ShaderCheck.h"
#include "render/gl/GlFormat.h"

#include <QRegularExpression>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

// The shipped names binding by use can place, and what each becomes. The
// normal matrix and the attenuation keep theirs: no use tells them apart
// from other matrices and vectors.
const std::vector<std::pair<const char *, const char *>> kRenamed = {
    {"modelViewMatrix", "q0"},
    {"projectionMatrix", "q1"},
    {"viewMatrix", "q2"},
    {"lightPosition", "q3"},
    {"lightCount", "q4"},
    {"shininess", "q5"},
    {"Ia", "q6"},
    {"ka", "q7"},
    {"kd", "q8"},
    {"ks", "q9"},
    {"Id", "q10"},
    {"Is", "q11"},
};

QByteArray renamed(QByteArray code)
{
    for (const auto &[from, to] : kRenamed)
        code = QString::fromUtf8(code)
                   .replace(QRegularExpression(QStringLiteral("\\b%1\\b").arg(from)),
                            QString::fromLatin1(to))
                   .toUtf8();
    return code;
}

ShaderPair meaningless(ShaderPair pair)
{
    pair.vertex.code = renamed(pair.vertex.code);
    pair.fragment.code = renamed(pair.fragment.code);
    return pair;
}

} // namespace

class TestBindByUse : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
        m_scene = loadCheckScene();
        m_reference = makeTestCheckReference(m_scene);
        QVERIFY_OK(m_offscreen.create());
        QVERIFY_OK(m_offscreen.renderer().setScene(m_scene));
    }

    void correctPairIsBoundAndPasses()
    {
        const ShaderPair pair = meaningless(shippedPhong());
        QVERIFY(!pair.fragment.code.contains("shininess"));
        const RgbImage image = drawPair(m_offscreen, pair, QSize(kCheckWidth, kCheckHeight));
        const ProgramBindings &bindings = m_offscreen.renderer().program().bindings();
        for (const VariableBinding *b : bindings.unboundUniforms())
            QFAIL(qPrintable(QStringLiteral("%1 is bound to nothing").arg(b->variable.name)));
        int byUse = 0;
        for (const VariableBinding &b : bindings.variables)
            byUse += b.byUse ? 1 : 0;
        QVERIFY2(byUse >= int(kRenamed.size()) - 2, qPrintable(QString::number(byUse)));
        const CheckReport report = checkRender(image, m_reference);
        QVERIFY2(report.passed(), qPrintable(checkSummary(report)));
    }

    void eachMistakeIsStillNamed_data()
    {
        QTest::addColumn<int>("key");
        for (ShaderMistake m :
             {ShaderMistake::NormalMatrix, ShaderMistake::LightSpace, ShaderMistake::HomogeneousW,
              ShaderMistake::ReflectIncident, ShaderMistake::ViewVector, ShaderMistake::Attenuation,
              ShaderMistake::NegativeLight, ShaderMistake::Ambient, ShaderMistake::HalfwayVector,
              ShaderMistake::Unnormalized})
            QTest::newRow(qPrintable(shaderMistakeKey(m))) << int(m);
    }

    void eachMistakeIsStillNamed()
    {
        QFETCH(int, key);
        const ShaderMistake mistake = ShaderMistake(key);
        const ShaderPair pair = meaningless(withMistake(mistake));
        const RgbImage image = drawPair(m_offscreen, pair, QSize(kCheckWidth, kCheckHeight));
        QVERIFY(m_offscreen.renderer().program().bindings().unboundUniforms().empty());
        const CheckReport report = checkRender(image, m_reference);
        QVERIFY2(!report.passed(), qPrintable(shaderMistakeKey(mistake)));
        const MistakeDiagnosis &d = report.diagnosis;
        bool named = !d.findings.empty() && d.findings.front().key == mistake;
        for (MistakeVariant v : d.together.variants)
            named = named || (d.togetherExplains() && v.key == mistake);
        if (!d.findings.empty())
            for (ShaderMistake also : d.findings.front().also)
                named = named || also == mistake;
        QVERIFY2(
            named,
            qPrintable(shaderMistakeKey(mistake) + QStringLiteral(": ") + checkSummary(report)));
    }

private:
    Scene m_scene;
    CheckReference m_reference;
    OffscreenRenderer m_offscreen;
};

QTEST_MAIN(TestBindByUse)
#include "tst_bindbyuse.moc"
