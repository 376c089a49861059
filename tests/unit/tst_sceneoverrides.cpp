// What render, check and grade say over a scene's words on the student's
// program (cli/common/SceneOverrides): --bind meanings and constants, --define,
// --precision, read the one way, applied name by name, and handed to
// grade's children as the same words.
#include "cli/common/SceneOverrides.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::cli;

namespace {

QString read(const QStringList &arguments, SceneOverrides *out)
{
    QCommandLineParser parser;
    const SceneOverrideOptions options(SceneOverrideOptions::Use::Check);
    parser.addOptions(options.all());
    if (!parser.parse(QStringList{QStringLiteral("phonglab")} + arguments))
        return parser.errorText();
    return readSceneOverrides(parser, options, out);
}

} // namespace

class TestSceneOverrides : public QObject
{
    Q_OBJECT

private slots:
    void meaningsConstantsDefinesAndPrecision()
    {
        SceneOverrides o;
        QCOMPARE(read({QStringLiteral("--bind"), QStringLiteral("uThing=model"),
                       QStringLiteral("--bind"), QStringLiteral("mode=1"), QStringLiteral("--bind"),
                       QStringLiteral("u_MatlSet[0].emit=0,0.5,-1"), QStringLiteral("--define"),
                       QStringLiteral("NUM_LIGHTS=2"), QStringLiteral("--precision"),
                       QStringLiteral("as-written")},
                      &o),
                 QString());
        QVERIFY(o.bindings.at(QStringLiteral("uThing")) == BindingMeaning::Model);
        QCOMPARE(o.constants.at(QStringLiteral("mode")), std::vector<double>{1.0});
        QCOMPARE(o.constants.at(QStringLiteral("u_MatlSet[0].emit")),
                 (std::vector<double>{0.0, 0.5, -1.0}));
        QCOMPARE(o.defines.at(QStringLiteral("NUM_LIGHTS")), QStringLiteral("2"));
        QVERIFY(o.precision == PrecisionRule::AsWritten);

        Scene scene;
        scene.uniforms[QStringLiteral("mode")] = {0.0};
        scene.course.defines[QStringLiteral("OTHER")] = QStringLiteral("x");
        o.applyTo(scene);
        QCOMPARE(scene.uniforms.at(QStringLiteral("mode")), std::vector<double>{1.0});
        QVERIFY(!scene.bindings.at(QStringLiteral("mode"))); // the page's value, no meaning
        QCOMPARE(scene.course.defines.size(), std::size_t(2));
        QVERIFY(scene.course.precision == PrecisionRule::AsWritten);

        // Grade's child is told the same.
        SceneOverrides again;
        QCOMPARE(read(o.arguments(), &again), QString());
        QVERIFY(again.bindings == o.bindings);
        QVERIFY(again.constants == o.constants);
        QVERIFY(again.defines == o.defines);
        QVERIFY(again.precision == o.precision);
    }

    void wrongWordsAreSaid_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown meaning")
            << QStringList{QStringLiteral("--bind"), QStringLiteral("u=modle")}
            << QStringLiteral("unknown meaning");
        QTest::newRow("define not identifier")
            << QStringList{QStringLiteral("--define"), QStringLiteral("2N=1")}
            << QStringLiteral("GLSL identifier");
        QTest::newRow("precision unknown")
            << QStringList{QStringLiteral("--precision"), QStringLiteral("mediump")}
            << QStringLiteral("highp or as-written");
    }

    void wrongWordsAreSaid()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, mentions);
        SceneOverrides o;
        const QString error = read(arguments, &o);
        QVERIFY2(error.contains(mentions), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestSceneOverrides)
#include "tst_sceneoverrides.moc"
