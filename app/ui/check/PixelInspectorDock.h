#pragma once
#include "core/check/PixelTerms.h"

#include <QColor>
#include <QDockWidget>
#include <optional>

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace phonglab {

// The pixel inspector: a clicked pixel's colour in your render and in the
// exact image, and the exact terms of the equation there (PixelTerms), as
// text that can be copied.
class PixelInspectorDock : public QDockWidget
{
    Q_OBJECT

public:
    explicit PixelInspectorDock(QWidget *parent = nullptr);

    void showPixel(const PixelTerms &terms, QColor yours, QColor exact);
    void showMessage(const QString &message); // no pixel: why
    QString text() const;                     // what Copy puts on the clipboard

private:
    QLabel *m_yours = nullptr;
    QLabel *m_exact = nullptr;
    QPlainTextEdit *m_terms = nullptr;
    QPushButton *m_copy = nullptr;
};

} // namespace phonglab
