// PhongLab under a German desktop (LANG=de_DE.UTF-8). The menus
// read Datei / Bearbeiten / Ansicht / Hilfe, the live check's status is
// German, View → Language offers both languages and remembers a choice,
// and a value typed the German way ("0,5") is saved as 0.5: the scene loads
// identically under C and passes `phonglab check`.
#include "PhonglabProcess.h"
#include "ResultChecks.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/scene/SceneJson.h"
#include "core/support/Language.h"
#include "ui/check/LiveCheck.h"
#include "ui/scene/MaterialDock.h"
#include "ui/scene/SceneEditDockSet.h"
#include "ui/scene/Vec3Field.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/LanguageMenu.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QAction>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kCheckTimeoutMs = 30000;

QString plain(QString text)
{
    return text.remove(QLatin1Char('&'));
}

} // namespace

class TestLanguage : public QObject, public UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        m_env.isolate();
        QSettings().remove(QStringLiteral("ui/language"));
        // A German desktop, as the window sees it when it starts there.
        for (const char *name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES"})
            qunsetenv(name);
        qputenv("LANG", "de_DE.UTF-8");
        QCOMPARE(languageFromEnvironment(), QStringLiteral("de"));
        // The numbers follow the language, whatever the desktop's locale
        // says ("9,024 Dreiecke" beside "36,2 dB").
        QLocale::setDefault(QLocale::c());
        useLanguage(languageFromEnvironment());
        QCOMPARE(QLocale().language(), QLocale::German);
        QCOMPARE(QLocale().toString(9024), QStringLiteral("9024"));
        QCOMPARE(QLocale().toString(0.95), QStringLiteral("0,95"));
        bool ok = true;
        QLocale().toDouble(QStringLiteral("1.5"), &ok);
        QVERIFY(!ok); // not 15: the field reads it as written (Vec3Field)
    }

    void cleanupTestCase()
    {
        useLanguage(QStringLiteral("en"));
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral("."));
    }

    void menusAndCheckSpeakGerman()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/check.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        QStringList menus;
        for (QAction *action : m_window->menuBar()->actions())
            menus << plain(action->text());
        for (const char *expected : {"Datei", "Bearbeiten", "Ansicht", "Hilfe"})
            QVERIFY2(menus.contains(QString::fromUtf8(expected)), qPrintable(menus.join(u'|')));

        // The material's fields write German numbers ("0,6", not "0.6").
        QStringList fields;
        for (const QLineEdit *f : m_window->docks().material->findChildren<QLineEdit *>())
            fields << f->text();
        QVERIFY2(fields.join(u'|').contains(QLatin1Char(',')), qPrintable(fields.join(u'|')));
        QVERIFY2(!fields.join(u'|').contains(QLatin1Char('.')), qPrintable(fields.join(u'|')));

        // The slide's equation taken literally: a pass the status names in words.
        QVERIFY(typeTheSlidesEquationAndCheck(kCheckTimeoutMs));
        QVERIFY(!QTest::currentTestFailed());
        LiveCheck *check = m_window->liveCheck();
        const QString status = check->statusLabel()->verdict();
        QVERIFY2(status.startsWith(QStringLiteral("✓")), qPrintable(status));
        QVERIFY2(!status.contains(QStringLiteral("slide")), qPrintable(status));
        QVERIFY2(status.contains(QStringLiteral("Folie")), qPrintable(status));
    }

    void languageMenuRemembersAChoice()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        auto *german = m_window->findChild<QAction *>(QStringLiteral("language-de"));
        auto *english = m_window->findChild<QAction *>(QStringLiteral("language-en"));
        QVERIFY(german && english);
        QVERIFY(german->isChecked());                         // the language in use
        QCOMPARE(english->text(), QStringLiteral("English")); // each in its own words
        english->trigger();
        QCOMPARE(LanguageMenu::rememberedLanguage(), QStringLiteral("en"));
        const QString said = m_window->statusBar()->currentMessage();
        QVERIFY2(said.contains(QStringLiteral("English")) && said.contains(QStringLiteral("Start")),
                 qPrintable(said));
        german->trigger();
        QCOMPARE(LanguageMenu::rememberedLanguage(), QStringLiteral("de"));
        QSettings().remove(QStringLiteral("ui/language"));
    }

    // Number fields show and read the user's locale; the scene file does not
    // depend on it.
    void germanCommaIsSavedAsAPoint()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/check.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        Vec3Field *kd = m_window->editDocks()->materialDock()->field(MaterialField::Kd);
        for (int axis = 0; axis < 3; ++axis)
            kd->component(axis)->setText(QStringLiteral("0,5"));
        kd->commit();
        QCOMPARE(viewport()->currentScene().objects[0].material.kd, glm::dvec3(0.5));
        QVERIFY(kd->component(0)->text().contains(QLatin1Char(','))); // shown the German way

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("saved.json"));
        QVERIFY_OK(m_window->document()->save(path));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY2(text.contains("0.5") && !text.contains("0,5"), text.constData());

        QLocale::setDefault(QLocale::c());
        const SceneLoadResult loaded = loadSceneFile(path);
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QCOMPARE(loaded.scene->objects[0].material.kd, glm::dvec3(0.5));
        QCOMPARE(loaded.scene->objects.size(), savedScene().objects.size());
        const ProcessRun run = runPhonglabUnderLocale(
            {QStringLiteral("check"), path, QStringLiteral("--size"), QStringLiteral("320x240")},
            QStringLiteral("C"));
        QVERIFY2(run.exitCode == 0, run.out.constData());
    }

    void cleanup() { m_window.reset(); }
};

QTEST_MAIN(TestLanguage)
#include "tst_language.moc"
