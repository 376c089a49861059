#pragma once
#include <QMessageBox>

namespace phonglab {

// A warning over `parent` that does not block: neither a load finishing nor
// a drop ever waits on a dialog, and nothing stalls the event loop.
inline void openWarning(QWidget *parent, const QString &title, const QString &message,
                        QMessageBox::Icon icon = QMessageBox::Warning)
{
    auto *box = new QMessageBox(icon, title, message, QMessageBox::Ok, parent);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

// A message's first line, where a status bar has room for one.
inline QString firstLine(const QString &message)
{
    return message.section(QLatin1Char('\n'), 0, 0);
}

} // namespace phonglab
