// `phonglab check` as a script sees it: exit codes, the JSON keys, the
// diagnosis of a wrong shader with its lines, compile errors on the user's
// line, the heatmap file.
#include "PhonglabProcess.h"
#include "ShaderMutations.h"
#include "TestPaths.h"

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

const QString kSize = QStringLiteral("320x240"); // the size check.json tells every mistake apart at

QString checkScene()
{
    return sourcePath(QStringLiteral("assets/scenes/check.json"));
}

QJsonObject parseJson(const ProcessRun &r)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(r.out, &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject())
        qWarning("not one JSON object: %s\n%s", qPrintable(error.errorString()), r.out.constData());
    return doc.object();
}

// The object's keys, recursively, with the values a script compares
// (verdict, key, also, undetectable, the numbers): what must not change
// with the language. Sentences ("message", "form") are left out.
QJsonValue scriptView(const QJsonValue &value)
{
    if (value.isArray()) {
        QJsonArray out;
        for (const QJsonValue &v : value.toArray())
            out.append(scriptView(v));
        return out;
    }
    if (!value.isObject())
        return value;
    QJsonObject out;
    const QJsonObject o = value.toObject();
    for (auto it = o.begin(); it != o.end(); ++it) {
        const bool sentence = it.key() == QLatin1String("message")
            || it.key() == QLatin1String("form") || it.key() == QLatin1String("notes")
            || it.key() == QLatin1String("forms") || it.key() == QLatin1String("warnings");
        out.insert(it.key(), sentence ? QJsonValue(QStringLiteral("(text)")) : scriptView(*it));
    }
    return out;
}

} // namespace

class TestCliCheck : public QObject
{
    Q_OBJECT

private slots:
    // The few words that say what a binding means come out in the run's
    // language like the sentence around them (they stayed English once).
    void bindingDescriptionsSpeakTheRunsLanguage()
    {
        const QStringList args{QStringLiteral("check"),  checkScene(),
                               QStringLiteral("--size"), kSize,
                               QStringLiteral("--bind"), QStringLiteral("kd=model")};
        const ProcessRun english =
            runPhonglab(args + QStringList{QStringLiteral("--lang"), QStringLiteral("en")});
        const ProcessRun german =
            runPhonglab(args + QStringList{QStringLiteral("--lang"), QStringLiteral("de")});
        const QString en = QString::fromUtf8(english.out) + english.err;
        const QString de = QString::fromUtf8(german.out) + german.err;
        QVERIFY2(en.contains(QStringLiteral("cannot hold the model matrix (object to world)")),
                 qPrintable(en));
        QVERIFY2(de.contains(QStringLiteral("die Model-Matrix (Objekt- zu Weltkoordinaten)")),
                 qPrintable(de));
        QVERIFY2(!de.contains(QStringLiteral("the model matrix")), qPrintable(de));
        QCOMPARE(german.exitCode, english.exitCode);
    }

    // Under a German locale the verdict and the diagnosis are
    // German, in the slide's words; --json keeps its keys and key values.
    void germanLocaleSpeaksGermanButJsonKeepsItsKeys()
    {
        const QString frag = write(withMistake(ShaderMistake::ReflectIncident).fragment.code,
                                   QStringLiteral("de.frag"));
        const QStringList args{QStringLiteral("check"),      checkScene(),
                               QStringLiteral("--size"),     kSize,
                               QStringLiteral("--fragment"), frag};
        const ProcessRun english = runPhonglabUnderLocale(args, QStringLiteral("C"));
        const ProcessRun german = runPhonglabUnderLocale(args, QStringLiteral("de_DE.UTF-8"));
        QCOMPARE(english.exitCode, 1);
        QCOMPARE(german.exitCode, 1);
        const QString en = QString::fromUtf8(english.out);
        const QString de = QString::fromUtf8(german.out);
        QVERIFY2(en.contains(QStringLiteral("check: fail")), qPrintable(en));
        QVERIFY2(en.contains(QStringLiteral("incident vector")), qPrintable(en));
        QVERIFY2(!de.contains(QStringLiteral("check: fail")), qPrintable(de));
        QVERIFY2(de.contains(QStringLiteral("Einfallsvektor")), qPrintable(de)); // the slide's word
        QVERIFY2(de.contains(QStringLiteral("reflect-incident")), qPrintable(de)); // keys stay
        QVERIFY2(!de.contains(QStringLiteral("explains")), qPrintable(de));
        // --lang outranks the locale, both ways.
        QCOMPARE(runPhonglabUnderLocale(
                     args + QStringList{QStringLiteral("--lang"), QStringLiteral("de")},
                     QStringLiteral("C"))
                     .out,
                 german.out);
        QCOMPARE(runPhonglabUnderLocale(args + QStringList{QStringLiteral("--lang=en")},
                                        QStringLiteral("de_DE.UTF-8"))
                     .out,
                 english.out);

        const QStringList json = args + QStringList{QStringLiteral("--json")};
        const ProcessRun englishJson = runPhonglabUnderLocale(json, QStringLiteral("C"));
        const ProcessRun germanJson = runPhonglabUnderLocale(json, QStringLiteral("de_DE.UTF-8"));
        const QJsonObject e = parseJson(englishJson), g = parseJson(germanJson);
        QVERIFY(!e.isEmpty());
        QCOMPARE(scriptView(g), scriptView(e));
        QVERIFY(g != e); // the sentences in it are German
    }

    void unknownLanguageIsAUsageError()
    {
        const ProcessRun r = runPhonglab({QStringLiteral("check"), checkScene(),
                                          QStringLiteral("--lang"), QStringLiteral("fr")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("'fr'")), qPrintable(r.err));
        QCOMPARE(runPhonglab({QStringLiteral("--lang")}).exitCode, 2);
        // Refused before any command reads its arguments, still in the
        // desktop's language.
        const ProcessRun refused = runPhonglabUnderLocale(
            {QStringLiteral("check"), QStringLiteral("--lang"), QStringLiteral("fr")},
            QStringLiteral("de_DE.UTF-8"));
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(QStringLiteral("spricht 'fr' nicht")),
                 qPrintable(refused.err));
        // A usage error speaks the run's language too (the application is
        // made before the arguments are read); its exit status does not change.
        const ProcessRun german =
            runPhonglabUnderLocale({QStringLiteral("check")}, QStringLiteral("de_DE.UTF-8"));
        QCOMPARE(german.exitCode, 2);
        QVERIFY2(!german.err.contains(QStringLiteral("usage:"))
                     && german.err.contains(QStringLiteral("phonglab check SCENE.json")),
                 qPrintable(german.err));
    }

    void helpNamesCheckAndItsKeys()
    {
        const ProcessRun top = runPhonglab({QStringLiteral("--help")});
        QVERIFY(QString::fromLocal8Bit(top.out).contains(QStringLiteral("check")));
        const ProcessRun r = runPhonglab({QStringLiteral("check"), QStringLiteral("--help")});
        QCOMPARE(r.exitCode, 0);
        for (const QString &key : shaderMistakeKeys())
            QVERIFY2(QString::fromUtf8(r.out).contains(key), qPrintable(key));
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no scene") << QStringList{};
        QTest::newRow("two scenes") << QStringList{checkScene(), checkScene()};
        QTest::newRow("bad size") << QStringList{checkScene(), QStringLiteral("--size"),
                                                 QStringLiteral("0x5")};
        QTest::newRow("bad tolerance")
            << QStringList{checkScene(), QStringLiteral("--tolerance"), QStringLiteral("-1")};
        QTest::newRow("tolerance not a number")
            << QStringList{checkScene(), QStringLiteral("--tolerance"), QStringLiteral("two")};
        QTest::newRow("unknown shading")
            << QStringList{checkScene(), QStringLiteral("--shading"), QStringLiteral("toon")};
        QTest::newRow("unknown option")
            << QStringList{checkScene(), QStringLiteral("--frobnicate")};
    }

    void usageErrors()
    {
        QFETCH(QStringList, args);
        const ProcessRun r = runPhonglab(QStringList{QStringLiteral("check")} + args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("usage: phonglab check")), qPrintable(r.err));
    }

    void shippedShaderPasses()
    {
        const ProcessRun r =
            runPhonglab({QStringLiteral("check"), checkScene(), QStringLiteral("--size"), kSize,
                         QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + QString::fromUtf8(r.out)));
        const QJsonObject o = parseJson(r);
        for (const char *key : {"verdict", "psnr_db", "max_error", "bad_fraction", "worst",
                                "diagnosis", "undetectable", "errors"})
            QVERIFY2(o.contains(QLatin1String(key)), key);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("pass"));
        QVERIFY(o.value(QStringLiteral("max_error")).toInt() <= 2);
        QCOMPARE(o.value(QStringLiteral("bad_fraction")).toDouble(), 0.0);
        QVERIFY(o.value(QStringLiteral("diagnosis")).toArray().isEmpty());
        QVERIFY(o.value(QStringLiteral("undetectable")).toArray().isEmpty());
        QVERIFY(o.value(QStringLiteral("errors")).toArray().isEmpty());
        // Text: the verdict line first.
        const ProcessRun text =
            runPhonglab({QStringLiteral("check"), checkScene(), QStringLiteral("--size"), kSize});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.startsWith("check: pass"));
    }

    void wrongShaderIsDiagnosedWithItsLine()
    {
        const QString frag = write(withMistake(ShaderMistake::ReflectIncident).fragment.code,
                                   QStringLiteral("r.frag"));
        const QString diff = m_dir.filePath(QStringLiteral("diff.png"));
        const ProcessRun r =
            runPhonglab({QStringLiteral("check"), checkScene(), QStringLiteral("--size"), kSize,
                         QStringLiteral("--fragment"), frag, QStringLiteral("--json"),
                         QStringLiteral("--diff"), diff});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = parseJson(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("fail"));
        QVERIFY(o.value(QStringLiteral("max_error")).toInt() > 2);
        QVERIFY(o.value(QStringLiteral("bad_fraction")).toDouble() > 0.0);
        QVERIFY(o.value(QStringLiteral("psnr_db")).toDouble() < 40.0);
        const QJsonObject worst = o.value(QStringLiteral("worst")).toObject();
        QVERIFY(worst.value(QStringLiteral("x")).toInt() >= 0
                && worst.value(QStringLiteral("x")).toInt() < 320);
        QVERIFY(worst.value(QStringLiteral("object")).toInt(-1) >= 0);
        const QJsonObject top = o.value(QStringLiteral("diagnosis")).toArray().first().toObject();
        QCOMPARE(top.value(QStringLiteral("key")).toString(), QStringLiteral("reflect-incident"));
        QCOMPARE(top.value(QStringLiteral("also")).toArray(),
                 QJsonArray{QStringLiteral("view-vector")});
        QVERIFY(top.value(QStringLiteral("confidence")).toDouble() >= 0.5);
        QVERIFY(top.value(QStringLiteral("message"))
                    .toString()
                    .contains(QStringLiteral("reflect(-L, N)")));
        // Both candidate lines: the reflect() and the definition of V.
        const QStringList source =
            QString::fromUtf8(withMistake(ShaderMistake::ReflectIncident).fragment.code)
                .split(QLatin1Char('\n'));
        QStringList named;
        for (const QJsonValue &v : top.value(QStringLiteral("lines")).toArray()) {
            const QJsonObject line = v.toObject();
            QCOMPARE(line.value(QStringLiteral("file")).toString(), frag);
            named << source.value(line.value(QStringLiteral("line")).toInt() - 1).trimmed();
        }
        QVERIFY2(named.filter(QStringLiteral("reflect(L, N)")).size() == 1,
                 qPrintable(named.join(QLatin1Char('|'))));
        QVERIFY2(named.filter(QStringLiteral("vec3 V =")).size() == 1,
                 qPrintable(named.join(QLatin1Char('|'))));
        const QImage heatmap(diff);
        QCOMPARE(heatmap.size(), QSize(320, 240));
    }

    void unexplainedDifferenceIsUnknown()
    {
        QByteArray code = shippedPhong().fragment.code;
        QVERIFY(code.contains("fragColor = vec4(I, 1.0);"));
        code.replace("fragColor = vec4(I, 1.0);", "fragColor = vec4(I.bgr, 1.0);");
        const ProcessRun r =
            runPhonglab({QStringLiteral("check"), checkScene(), QStringLiteral("--size"), kSize,
                         QStringLiteral("--fragment"), write(code, QStringLiteral("bgr.frag")),
                         QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject top =
            parseJson(r).value(QStringLiteral("diagnosis")).toArray().first().toObject();
        QCOMPARE(top.value(QStringLiteral("key")).toString(), QStringLiteral("unknown"));
    }

    void compileErrorIsAnError()
    {
        const QString frag = testDataPath(QStringLiteral("shaders/error_line17.frag"));
        const ProcessRun r =
            runPhonglab({QStringLiteral("check"), checkScene(), QStringLiteral("--size"), kSize,
                         QStringLiteral("--fragment"), frag, QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(frag + QStringLiteral(":17:9: error: ")), qPrintable(r.err));
        const QJsonObject o = parseJson(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("error"));
        const QJsonObject e = o.value(QStringLiteral("errors")).toArray().first().toObject();
        QCOMPARE(e.value(QStringLiteral("file")).toString(), frag);
        QCOMPARE(e.value(QStringLiteral("line")).toInt(), 17);
        QCOMPARE(e.value(QStringLiteral("column")).toInt(), 9);
        QVERIFY(!e.value(QStringLiteral("message")).toString().isEmpty());
    }

    void uniformScaleHidesNormalMatrix()
    {
        // The shipped sphere scene scales nothing: N moved by the model-view
        // matrix is still perpendicular, so that mistake cannot show there.
        const ProcessRun r = runPhonglab(
            {QStringLiteral("check"), sourcePath(QStringLiteral("assets/scenes/sphere.json")),
             QStringLiteral("--size"), kSize, QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray hidden = parseJson(r).value(QStringLiteral("undetectable")).toArray();
        QVERIFY2(hidden.contains(QStringLiteral("normal-matrix")), r.out.constData());
    }

    void nothingToCompareIsAnError()
    {
        // At 4x3 every covered pixel lies in the silhouette band: no
        // verdict, so no grader fails (or passes) a shader on it.
        const ProcessRun r =
            runPhonglab({QStringLiteral("check"), checkScene(), QStringLiteral("--size"),
                         QStringLiteral("4x3"), QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = parseJson(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("error"));
        QVERIFY(o.value(QStringLiteral("errors"))
                    .toArray()
                    .first()
                    .toObject()
                    .value(QStringLiteral("message"))
                    .toString()
                    .contains(QStringLiteral("nothing to compare")));
    }

    void badSceneIsAnError()
    {
        const ProcessRun r =
            runPhonglab({QStringLiteral("check"), m_dir.filePath(QStringLiteral("missing.json")),
                         QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = parseJson(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("error"));
        QCOMPARE(o.value(QStringLiteral("errors")).toArray().size(), 1);
    }

private:
    QString write(const QByteArray &code, const QString &name)
    {
        const QString path = m_dir.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(code) != code.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestCliCheck)
#include "tst_clicheck.moc"
