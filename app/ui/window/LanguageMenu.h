#pragma once
#include <QObject>
#include <QString>

class QActionGroup;
class QMenu;

namespace phonglab {

// View → Language: the languages PhongLab speaks, each named in its own
// words (English, Deutsch), the one in use checked. A choice is remembered
// (QSettings "ui/language") and applies from the next start, as it would
// take every open dialog and dock to be rebuilt now; `phonglab --lang`
// overrides it for one run.
class LanguageMenu : public QObject
{
    Q_OBJECT

public:
    LanguageMenu(QMenu *menu, QObject *parent);

    // The remembered choice ("en", "de"; empty: none, the locale decides).
    static QString rememberedLanguage();

signals:
    // Said in the language in use, for the status bar.
    void chosen(const QString &message);

private:
    void choose(const QString &language);

    QActionGroup *m_group = nullptr;
};

} // namespace phonglab
