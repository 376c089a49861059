#include "AboutDialog.h"

#include <OpenMesh/Core/System/config.h>

#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace phonglab {

namespace {

constexpr int kIconSide = 96;

} // namespace

QString AboutDialog::openMeshVersion()
{
    // OM_VERSION is 0xVMMmm: the major in the fifth hex digit, then a byte
    // each for minor and patch (OpenMesh 9.0 is 0x90000); OM_GET_* decode it.
    return QStringLiteral("%1.%2.%3").arg(OM_GET_VER).arg(OM_GET_MAJ).arg(OM_GET_MIN);
}

QString AboutDialog::versionReport(const QString &glRenderer)
{
    const QString version = QCoreApplication::applicationVersion();
    QStringList lines;
    lines << tr("PhongLab: %1").arg(version.isEmpty() ? tr("unknown version") : version);
    lines << tr("Qt: %1 (built against %2)")
                 .arg(QString::fromLatin1(qVersion()), QStringLiteral(QT_VERSION_STR));
    lines << tr("OpenGL: %1")
                 .arg(glRenderer.isEmpty() ? tr("not started yet (the 3D view has not drawn)")
                                           : glRenderer);
    lines << tr("OpenMesh: %1").arg(openMeshVersion());
    lines << tr("Platform: %1, %2")
                 .arg(QSysInfo::prettyProductName(), QGuiApplication::platformName());
    return lines.join(QLatin1Char('\n'));
}

AboutDialog::AboutDialog(const QString &glRenderer, QWidget *parent)
    : QDialog(parent)
    , m_report(versionReport(glRenderer))
{
    setWindowTitle(tr("About PhongLab"));
    auto *icon = new QLabel(this);
    icon->setPixmap(QApplication::windowIcon().pixmap(kIconSide, kIconSide));
    icon->setAlignment(Qt::AlignTop);

    // The licence as packaging/debian/copyright states it.
    QString about =
        tr("<h2>PhongLab</h2><p>A shader editor for the Phong illumination model: edit the "
           "shaders while they run, and check them against the exact answer.</p>"
           "<p>Free software under the GNU General Public License, version 3 or later.</p>");
    auto *heading = new QLabel(about, this);
    heading->setWordWrap(true);
    heading->setOpenExternalLinks(true);
    auto *report = new QLabel(m_report, this);
    report->setTextInteractionFlags(Qt::TextSelectableByMouse);
    report->setObjectName(QStringLiteral("versionReport"));

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton *copy = buttons->addButton(tr("&Copy"), QDialogButtonBox::ActionRole);
    copy->setToolTip(tr("Copy the versions, for a bug report"));
    connect(copy, &QPushButton::clicked, this,
            [this] { QGuiApplication::clipboard()->setText(m_report); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *text = new QVBoxLayout;
    text->addWidget(heading);
    text->addWidget(report);
    text->addStretch();
    auto *row = new QHBoxLayout;
    row->addWidget(icon);
    row->addLayout(text, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(row);
    layout->addWidget(buttons);
}

} // namespace phonglab
