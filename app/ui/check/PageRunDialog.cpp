#include "PageRunDialog.h"

#include "render/page/PageCheckOutput.h"

#include <QGridLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QProgressBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

namespace phonglab {

namespace {

constexpr int kFrameSide = 280; // each picture's larger side on screen

QPixmap shown(const QImage &image)
{
    if (image.isNull())
        return {};
    return QPixmap::fromImage(
        image.scaled(kFrameSide, kFrameSide, Qt::KeepAspectRatio, Qt::SmoothTransformation));
}

} // namespace

PageRunDialog::PageRunDialog(const PageRequest &request, QWidget *parent)
    : QDialog(parent)
    , m_request(request)
{
    setObjectName(QStringLiteral("pageRunDialog"));
    setWindowTitle(tr("Run the Page"));
    auto *layout = new QVBoxLayout(this);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("pageRunStatus"));
    m_status->setWordWrap(true);
    m_status->setTextFormat(Qt::PlainText); // a page's own words are data
    layout->addWidget(m_status);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 0); // a browser run says nothing of how far it is
    layout->addWidget(m_progress);
    auto *frames = new QGridLayout;
    const QString captions[] = {tr("the browser"), tr("PhongLab, drawn again"), tr("difference")};
    QLabel **labels[] = {&m_browser, &m_drawn, &m_difference};
    const char *names[] = {"pageBrowserFrame", "pageDrawnFrame", "pageDifferenceFrame"};
    for (int i = 0; i < 3; ++i) {
        *labels[i] = frameLabel(QString::fromLatin1(names[i]));
        frames->addWidget(*labels[i], 0, i);
        auto *caption = new QLabel(captions[i], this);
        caption->setAlignment(Qt::AlignHCenter);
        frames->addWidget(caption, 1, i);
    }
    layout->addLayout(frames);
    m_findings = new QTextBrowser(this);
    m_findings->setObjectName(QStringLiteral("pageFindings"));
    layout->addWidget(m_findings, 1);
    m_button = new QPushButton(tr("Cancel"), this);
    m_button->setObjectName(QStringLiteral("pageRunButton"));
    layout->addWidget(m_button, 0, Qt::AlignRight);
    connect(m_button, &QPushButton::clicked, this, &PageRunDialog::cancelOrClose);
    connect(&m_watcher, &QFutureWatcher<PageCapturing>::finished, this, &PageRunDialog::showResult);
    resize(3 * kFrameSide + 80, 2 * kFrameSide + 160);
    start();
}

PageRunDialog::~PageRunDialog()
{
    // The run holds a browser: it stops at the next wait, and is waited for.
    m_cancelled->store(true);
    m_watcher.waitForFinished();
}

QLabel *PageRunDialog::frameLabel(const QString &objectName)
{
    auto *label = new QLabel(this);
    label->setObjectName(objectName);
    label->setMinimumSize(kFrameSide, kFrameSide);
    label->setAlignment(Qt::AlignCenter);
    return label;
}

void PageRunDialog::start()
{
    m_status->setText(tr("Running %1 in Chromium (headless, WebGL on SwiftShader, no network)…")
                          .arg(m_request.run.folders.project));
    PageRequest request = m_request;
    const std::shared_ptr<std::atomic<bool>> cancelled = m_cancelled;
    request.run.cancelled = [cancelled] { return cancelled->load(); };
    m_watcher.setFuture(QtConcurrent::run([request] { return capturePage(request); }));
}

void PageRunDialog::showResult()
{
    // The checks draw the frame again: on this thread, which may make a context.
    m_check = checkCapturedPage(m_watcher.result(), m_request);
    m_finished = true;
    m_progress->hide();
    m_button->setText(tr("Close"));
    if (m_cancelled->load() && !m_check.ok()) {
        m_status->setText(tr("Cancelled."));
        emit runFinished();
        return;
    }
    m_status->setText(m_check.ok() ? tr("Frame %1 of %2, as the browser drew it.")
                                         .arg(m_check.capture.frame)
                                         .arg(m_check.capture.page)
                                   : tr("The page was not run: %1").arg(m_check.error));
    const QSize size = m_check.capture.canvas;
    m_browser->setPixmap(shown(pageFrameImage(m_check.capture.pixels, size)));
    m_drawn->setPixmap(shown(pageFrameImage(m_check.replayPixels, size)));
    m_difference->setPixmap(shown(pageDifferenceImage(m_check)));
    m_findings->setPlainText(findingsText());
    emit runFinished();
}

QString PageRunDialog::findingsText() const
{
    return pageText(m_check).join(QLatin1Char('\n'));
}

void PageRunDialog::cancelOrClose()
{
    if (m_finished) {
        accept();
        return;
    }
    m_cancelled->store(true);
    m_status->setText(tr("Cancelling…"));
}

} // namespace phonglab
