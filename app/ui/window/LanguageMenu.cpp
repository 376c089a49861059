#include "LanguageMenu.h"

#include "core/support/Language.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QSettings>

namespace phonglab {

namespace {

const char *const kSettingsKey = "ui/language";

// Each language in its own words: a user who cannot read the current one
// still finds theirs.
QString nativeName(const QString &language)
{
    return language == QLatin1String("de") ? QStringLiteral("Deutsch") : QStringLiteral("English");
}

} // namespace

LanguageMenu::LanguageMenu(QMenu *menu, QObject *parent)
    : QObject(parent)
    , m_group(new QActionGroup(this))
{
    for (const QString &language : spokenLanguages()) {
        QAction *action = menu->addAction(nativeName(language));
        action->setObjectName(QStringLiteral("language-%1").arg(language));
        action->setCheckable(true);
        action->setChecked(language == currentLanguage());
        m_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, language] { choose(language); });
    }
}

QString LanguageMenu::rememberedLanguage()
{
    return spokenLanguage(QSettings().value(QLatin1String(kSettingsKey)).toString());
}

void LanguageMenu::choose(const QString &language)
{
    QSettings().setValue(QLatin1String(kSettingsKey), language);
    emit chosen(language == currentLanguage()
                    ? tr("PhongLab speaks %1.").arg(nativeName(language))
                    : tr("PhongLab will speak %1 from the next start.").arg(nativeName(language)));
}

} // namespace phonglab
