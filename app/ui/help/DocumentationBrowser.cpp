#include "DocumentationBrowser.h"

#include "DocumentView.h"
#include "DocumentationFiles.h"

#include <QAction>
#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QListWidget>
#include <QSplitter>
#include <QStyle>
#include <QToolBar>
#include <QVBoxLayout>

namespace phonglab {

namespace {

constexpr int kContentsWidth = 300;                           // the longest title
constexpr int kPageWidth = DocumentView::kMaxImageWidth + 60; // the widest image, and margins
const QSize kDefaultSize(1140, 780);

bool isMarkdown(const QFileInfo &file)
{
    return file.suffix().compare(QLatin1String("md"), Qt::CaseInsensitive) == 0;
}

QString withoutFragment(const QUrl &url)
{
    return QDir::cleanPath(url.adjusted(QUrl::RemoveFragment | QUrl::RemoveQuery).toLocalFile());
}

} // namespace

DocumentationBrowser::DocumentationBrowser(const QString &folder, QWidget *parent)
    : QWidget(parent, Qt::Window) // its own window: read beside the editor, not over it
    , m_folder(folder)
    , m_documents(documentationFiles(folder))
    , m_view(new DocumentView(this))
    , m_contents(new QListWidget(this))
    , m_note(new QLabel(this))
{
    setWindowTitle(tr("PhongLab Documentation"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(createToolBar());

    for (const QString &path : m_documents) {
        auto *item = new QListWidgetItem(documentTitle(path), m_contents);
        item->setData(Qt::UserRole, path);
        item->setToolTip(QDir(m_folder).relativeFilePath(path));
    }
    connect(m_contents, &QListWidget::currentItemChanged, this, [this](QListWidgetItem *item) {
        if (item)
            openDocument(QUrl::fromLocalFile(item->data(Qt::UserRole).toString()));
    });

    // Links are followed here, not by QTextBrowser: it would show an empty
    // page for a file that is not there and cannot open a scene or a folder.
    m_view->setOpenLinks(false);
    connect(m_view, &QTextBrowser::anchorClicked, this, &DocumentationBrowser::followLink);
    connect(m_view, &QTextBrowser::sourceChanged, this, &DocumentationBrowser::showingChanged);
    connect(m_view, &QTextBrowser::highlighted, this,
            [this](const QUrl &link) { m_note->setText(link.toString()); });

    auto *splitter = new QSplitter(this);
    splitter->addWidget(m_contents);
    splitter->addWidget(m_view);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({kContentsWidth, kPageWidth});
    layout->addWidget(splitter, 1);
    m_note->setContentsMargins(6, 2, 6, 2);
    m_note->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_note);
    resize(kDefaultSize);
    openHome();
}

QToolBar *DocumentationBrowser::createToolBar()
{
    auto *bar = new QToolBar(this);
    m_back = bar->addAction(style()->standardIcon(QStyle::SP_ArrowBack), tr("Back"), m_view,
                            &QTextBrowser::backward);
    m_back->setShortcut(QKeySequence::Back);
    m_forward = bar->addAction(style()->standardIcon(QStyle::SP_ArrowForward), tr("Forward"),
                               m_view, &QTextBrowser::forward);
    m_forward->setShortcut(QKeySequence::Forward);
    bar->addAction(style()->standardIcon(QStyle::SP_DirHomeIcon), tr("Contents"), this,
                   &DocumentationBrowser::openHome);
    connect(m_view, &QTextBrowser::backwardAvailable, m_back, &QAction::setEnabled);
    connect(m_view, &QTextBrowser::forwardAvailable, m_forward, &QAction::setEnabled);
    m_back->setEnabled(false);
    m_forward->setEnabled(false);
    return bar;
}

void DocumentationBrowser::openHome()
{
    if (!m_documents.isEmpty())
        openDocument(QUrl::fromLocalFile(m_documents.front()));
}

void DocumentationBrowser::openDocument(const QUrl &file)
{
    m_note->clear();
    // Said outright, not left to a guess from the file's name.
    m_view->setSource(file, QTextDocument::MarkdownResource);
}

QUrl DocumentationBrowser::currentSource() const
{
    return m_view->source();
}

QString DocumentationBrowser::note() const
{
    return m_note->text();
}

void DocumentationBrowser::followLink(const QUrl &link)
{
    const QUrl url = m_view->source().resolved(link);
    if (!url.isLocalFile()) { // the web, mail: the only links that need a network
        QDesktopServices::openUrl(url);
        return;
    }
    const QFileInfo file(withoutFragment(url));
    if (!file.exists()) {
        m_note->setText(tr("%1 is not part of the documentation installed here (%2).")
                            .arg(link.toString(QUrl::RemoveFragment),
                                 QDir::toNativeSeparators(file.absoluteFilePath())));
        return;
    }
    if (isMarkdown(file))
        openDocument(url);
    else // a scene, an image, a folder: what the desktop opens it with
        QDesktopServices::openUrl(url);
}

// The list and the title follow the page, however it was reached.
void DocumentationBrowser::showingChanged(const QUrl &source)
{
    const QString shown = withoutFragment(source);
    const QSignalBlocker quiet(m_contents);
    for (int row = 0; row < m_contents->count(); ++row) {
        QListWidgetItem *item = m_contents->item(row);
        if (QDir::cleanPath(item->data(Qt::UserRole).toString()) == shown) {
            m_contents->setCurrentItem(item);
            break;
        }
    }
    setWindowTitle(tr("%1 — PhongLab Documentation").arg(documentTitle(shown)));
}

} // namespace phonglab
