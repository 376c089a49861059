#pragma once
#include <QUrl>
#include <QWidget>

class QAction;
class QLabel;
class QListWidget;
class QToolBar;

namespace phonglab {

class DocumentView;

// Help → Documentation: the shipped Markdown docs (DocumentationFiles.h) in a
// window of their own beside the editor, offline. The list on the left has
// every doc, README first; links between docs and their images work as on
// the web (relative to the file), with back and forward. A link to a file
// that is not a doc (a scene, a source file) opens outside; one to a file
// this installation lacks says so instead of showing an empty page.
class DocumentationBrowser : public QWidget
{
    Q_OBJECT

public:
    // `folder` holds README.md and docs/ (documentationFolder()).
    explicit DocumentationBrowser(const QString &folder, QWidget *parent = nullptr);

    // Shows a Markdown file (a file: URL, with or without #anchor).
    void openDocument(const QUrl &file);
    void openHome(); // README.md, or the first doc
    QUrl currentSource() const;
    QStringList documents() const { return m_documents; }

    DocumentView *view() const { return m_view; }
    QListWidget *contents() const { return m_contents; }
    QString note() const; // why the last link went nowhere; empty when it did

private:
    QToolBar *createToolBar();
    void followLink(const QUrl &link);
    void showingChanged(const QUrl &source);

    QString m_folder;
    QStringList m_documents;
    DocumentView *m_view = nullptr;
    QListWidget *m_contents = nullptr;
    QLabel *m_note = nullptr;
    QAction *m_back = nullptr;
    QAction *m_forward = nullptr;
};

} // namespace phonglab
