#pragma once
#include <QDialog>

namespace phonglab {

// Help → About PhongLab: what a bug report needs, selectable and with a Copy
// button: PhongLab's version, the Qt it runs on and was built against, the
// OpenGL version and renderer the 3D view got, and the OpenMesh it was built
// with.
class AboutDialog : public QDialog
{
    Q_OBJECT

public:
    // `glRenderer`: Viewport::glRendererName(), "OpenGL <GL_VERSION>
    // (<GL_RENDERER>)"; empty before the view has drawn.
    explicit AboutDialog(const QString &glRenderer, QWidget *parent = nullptr);

    // One "name: value" line each, as the dialog shows and copies them.
    static QString versionReport(const QString &glRenderer);
    // OM_VERSION as "major.minor.patch".
    static QString openMeshVersion();
    QString text() const { return m_report; }

private:
    QString m_report;
};

} // namespace phonglab
