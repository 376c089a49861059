#include "PixelInspectorDock.h"

#include <QApplication>
#include <QClipboard>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace phonglab {

namespace {

QString swatch(const QString &name, QColor c)
{
    return QStringLiteral(
               "<span style=\"background:%1\">&nbsp;&nbsp;&nbsp;&nbsp;</span> %2 (%3, %4, %5)")
        .arg(c.name(), name)
        .arg(c.red())
        .arg(c.green())
        .arg(c.blue());
}

} // namespace

PixelInspectorDock::PixelInspectorDock(QWidget *parent)
    : QDockWidget(tr("Pixel Inspector"), parent)
{
    setObjectName(QStringLiteral("pixelInspectorDock"));
    auto *body = new QWidget(this);
    auto *layout = new QVBoxLayout(body);
    auto *colours = new QHBoxLayout;
    m_yours = new QLabel(body);
    m_exact = new QLabel(body);
    colours->addWidget(m_yours);
    colours->addWidget(m_exact);
    colours->addStretch();
    layout->addLayout(colours);
    m_terms = new QPlainTextEdit(body);
    m_terms->setReadOnly(true);
    m_terms->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    layout->addWidget(m_terms);
    m_copy = new QPushButton(tr("Copy"), body);
    m_copy->setToolTip(tr("Copy the values as text"));
    layout->addWidget(m_copy, 0, Qt::AlignRight);
    connect(m_copy, &QPushButton::clicked, this,
            [this] { QApplication::clipboard()->setText(text()); });
    setWidget(body);
    showMessage(
        tr("Turn on Inspect (I) and click a pixel, or Ctrl+click one, to see the terms of the "
           "equation there."));
}

void PixelInspectorDock::showPixel(const PixelTerms &terms, QColor yours, QColor exact)
{
    m_yours->setText(swatch(tr("yours"), yours));
    m_exact->setText(swatch(tr("exact"), exact));
    m_terms->setPlainText(QStringLiteral("yours    (%1, %2, %3)\nexact    (%4, %5, %6)\n")
                              .arg(yours.red())
                              .arg(yours.green())
                              .arg(yours.blue())
                              .arg(exact.red())
                              .arg(exact.green())
                              .arg(exact.blue())
                          + terms.toText());
    m_copy->setEnabled(true);
}

void PixelInspectorDock::showMessage(const QString &message)
{
    m_yours->clear();
    m_exact->clear();
    m_terms->setPlainText(message);
    m_copy->setEnabled(false);
}

QString PixelInspectorDock::text() const
{
    return m_terms->toPlainText();
}

} // namespace phonglab
