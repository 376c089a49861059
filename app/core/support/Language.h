#pragma once
#include <QLocale>
#include <QString>
#include <QStringList>

// Which language PhongLab speaks in a run, and loading its translations
// (translations/phonglab_<code>.ts, compiled into the program; Qt's own
// qtbase_<code>.qm from Qt's translation folder, for standard dialogs).
// English is the source language: it needs no file, and a string a
// translation lacks stays English, never empty.
//
// What never changes with the language: JSON keys, mistake keys, exit
// codes, CSV columns, file formats, command-line flags, and numbers in
// files (scenes are written with a '.' whatever the locale).
namespace phonglab {

// The languages PhongLab speaks, as codes: "en", "de".
QStringList spokenLanguages();
// `code` ("de", "de_DE.UTF-8", "German"?) as one of spokenLanguages(), or
// empty when PhongLab does not speak it.
QString spokenLanguage(const QString &code);
// The language the environment asks for, as gettext reads it: LANGUAGE (a
// colon-separated list of preferences) unless the locale is C or POSIX,
// then LC_ALL, LC_MESSAGES, LANG; the first PhongLab speaks. "en" when
// none names one.
QString languageFromEnvironment();

// Takes `--lang CODE` or `--lang=CODE` out of the command line (any
// command, or the window), so that no command's own parser sees it. Once
// a Q*Application is made, the run speaks that language (else the
// environment's). Not ok for a value PhongLab does not speak or a missing
// one: languageOptionError() says so.
struct LanguageOption {
    bool ok = true;
    QString language; // empty: not given
    QString refused;  // the value not spoken; empty when none was given
};
LanguageOption takeLanguageOption(int &argc, char **argv);
// Why `option` is not ok, in the environment's language: made once a
// Q*Application exists (before one, it is English).
QString languageOptionError(const LanguageOption &option);
// Whether this run was given `--lang` (which outranks the window's
// remembered choice).
bool languageRequested();
// The language the run speaks now (after the application object is made).
QString currentLanguage();
// Speaks `language` from now on: PhongLab's and Qt's translators replaced
// (none for English). For the window, whose remembered choice applies
// after the application object exists. Needs a Q*Application.
void useLanguage(const QString &language);
// The locale for numbers inside the run's sentences: "12,5 %" and "2.683"
// when it speaks German, the C locale ("12.5 %", "2683") in English, so
// English output reads as it always has. Never for what a script reads:
// files, JSON and CSV keep the C locale.
QLocale sentenceLocale();
// `value` written as the run's sentences write numbers (sentenceLocale()).
QString sentenceNumber(double value, char format = 'g', int precision = 6);
// The locale of the window's numbers (useLanguage() makes it the default):
// the desktop's where it speaks the run's language, else the language's;
// no group separators.
QLocale numberLocale();

} // namespace phonglab
