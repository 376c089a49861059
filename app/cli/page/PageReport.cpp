#include "PageReport.h"

#include "cli/common/CliCommon.h"
#include "render/page/PageCheckOutput.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>

namespace phonglab::cli {

struct PageReportWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::PageReport)
};

namespace {

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

} // namespace

int reportPageAlone(const PageCheck &check, bool json, const QString &note)
{
    const bool passed = check.ok() && !check.javascriptMistakes() && !check.ownSceneFails();
    const QString verdict = !check.ok() ? key("error") : passed ? key("pass") : key("fail");
    if (json) {
        QJsonObject out{{key("verdict"), verdict}, {key("page"), pageJson(check)}};
        if (!note.isEmpty())
            out.insert(key("notes"), QJsonArray{note});
        printLine(QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Indented)).trimmed());
    } else {
        if (!check.ok())
            printError(check.error);
        for (const QString &line :
             pageText(check) + (note.isEmpty() ? QStringList() : QStringList{note}))
            printLine(line);
        printLine(PageReportWords::tr("verdict: %1").arg(verdict));
    }
    return passed ? kExitOk : kExitFailure;
}

} // namespace phonglab::cli
