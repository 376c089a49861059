#include "Language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>
#include <cstring>
#include <memory>

namespace phonglab {

namespace {

struct LanguageWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::Language)
};

QString &requestedLanguage()
{
    static QString language; // from --lang; empty: the environment decides
    return language;
}

QString &spokenNow()
{
    static QString language = QStringLiteral("en");
    return language;
}

// Installed translators live as long as the application (which does not own them).
std::unique_ptr<QTranslator> &ownTranslator()
{
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

std::unique_ptr<QTranslator> &qtTranslator()
{
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

void removeTranslator(std::unique_ptr<QTranslator> &translator)
{
    if (translator)
        QCoreApplication::removeTranslator(translator.get());
    translator.reset();
}

bool isPosixLocale(const QString &value)
{
    return value == QLatin1String("C") || value.startsWith(QLatin1String("C."))
        || value == QLatin1String("POSIX");
}

// Each application made (a command's or the window's) speaks the language
// asked for from its start.
void installRequestedLanguage()
{
    const QString requested = requestedLanguage();
    useLanguage(requested.isEmpty() ? languageFromEnvironment() : requested);
}

} // namespace

Q_COREAPP_STARTUP_FUNCTION(installRequestedLanguage)

QStringList spokenLanguages()
{
    return {QStringLiteral("en"), QStringLiteral("de")};
}

QString spokenLanguage(const QString &code)
{
    // "de_DE.UTF-8@euro" -> "de"
    const QString language = code.section(QLatin1Char('.'), 0, 0)
                                 .section(QLatin1Char('@'), 0, 0)
                                 .section(QLatin1Char('_'), 0, 0)
                                 .section(QLatin1Char('-'), 0, 0)
                                 .toLower();
    return spokenLanguages().contains(language) ? language : QString();
}

QString languageFromEnvironment()
{
    QString locale;
    for (const char *name : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
        locale = qEnvironmentVariable(name);
        if (!locale.isEmpty())
            break;
    }
    if (!isPosixLocale(locale)) {
        const QStringList preferred =
            qEnvironmentVariable("LANGUAGE").split(QLatin1Char(':'), Qt::SkipEmptyParts);
        for (const QString &entry : preferred)
            if (const QString spoken = spokenLanguage(entry); !spoken.isEmpty())
                return spoken;
    }
    const QString spoken = spokenLanguage(locale);
    return spoken.isEmpty() ? QStringLiteral("en") : spoken;
}

LanguageOption takeLanguageOption(int &argc, char **argv)
{
    LanguageOption option;
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        const char *argument = argv[i];
        if (std::strcmp(argument, "--") == 0) { // what follows is file names
            while (i < argc)
                argv[kept++] = argv[i++];
            break;
        }
        QString value;
        bool found = false;
        if (std::strcmp(argument, "--lang") == 0) {
            found = true;
            if (i + 1 < argc)
                value = QString::fromLocal8Bit(argv[++i]);
        } else if (std::strncmp(argument, "--lang=", 7) == 0) {
            found = true;
            value = QString::fromLocal8Bit(argument + 7);
        }
        if (!found) {
            argv[kept++] = argv[i];
            continue;
        }
        const QString spoken = spokenLanguages().contains(value) ? value : QString();
        if (spoken.isEmpty()) {
            option.ok = false;
            option.refused = value;
        } else {
            option.language = spoken;
        }
    }
    argv[kept] = nullptr;
    argc = kept;
    if (option.ok && !option.language.isEmpty())
        requestedLanguage() = option.language;
    return option;
}

bool languageRequested()
{
    return !requestedLanguage().isEmpty();
}

QString currentLanguage()
{
    return spokenNow();
}

void useLanguage(const QString &language)
{
    removeTranslator(ownTranslator());
    removeTranslator(qtTranslator());
    const QString spoken = spokenLanguage(language);
    spokenNow() = spoken.isEmpty() ? QStringLiteral("en") : spoken;
    // The window's numbers (fields, counts) as its sentences write them: a
    // German run on an English desktop wrote "9,024 Dreiecke" beside "36,2 dB".
    QLocale::setDefault(numberLocale());
    if (spokenNow() == QLatin1String("en"))
        return;
    auto own = std::make_unique<QTranslator>();
    if (own->load(QStringLiteral(":/translations/phonglab_%1.qm").arg(spokenNow()))) {
        QCoreApplication::installTranslator(own.get());
        ownTranslator() = std::move(own);
    }
    auto qt = std::make_unique<QTranslator>();
    if (qt->load(QStringLiteral("qtbase_%1").arg(spokenNow()),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt.get());
        qtTranslator() = std::move(qt);
    }
}

QString languageOptionError(const LanguageOption &option)
{
    return option.refused.isEmpty()
        ? LanguageWords::tr("--lang needs a language: en or de")
        : LanguageWords::tr("--lang: PhongLab does not speak '%1' (en or de)").arg(option.refused);
}

QLocale numberLocale()
{
    const QLocale system = QLocale::system();
    const bool german = currentLanguage() == QLatin1String("de");
    QLocale out = german
        ? (system.language() == QLocale::German ? system
                                                : QLocale(QLocale::German, QLocale::Germany))
        : (system.language() == QLocale::English ? system : QLocale::c());
    // "1.5" typed in a German field is not 15: no group separators, read or written.
    out.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    return out;
}

QLocale sentenceLocale()
{
    return currentLanguage() == QLatin1String("de") ? QLocale(QLocale::German, QLocale::Germany)
                                                    : QLocale::c();
}

QString sentenceNumber(double value, char format, int precision)
{
    return sentenceLocale().toString(value, format, precision);
}

} // namespace phonglab
