#pragma once
#include <QMainWindow>

class QAction;
class QLabel;

namespace phonglab {

class Viewport;

// The editor window: the Viewport in the middle, File and View menus, and a
// status bar with frame time, triangle count and the OpenGL renderer.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);

    // Load / save without any dialog (startup, tests); false with a reason on
    // failure. A failed open keeps the current scene; saving writes the scene
    // with the camera as currently orbited.
    bool openScene(const QString &path, QString *error);
    bool saveScene(const QString &path, QString *error);

    QString scenePath() const { return m_scenePath; }
    Viewport *viewport() const { return m_viewport; }

private slots:
    void chooseAndOpenScene();
    void saveSceneToCurrentFile();
    void chooseAndSaveScene();
    void showFrameStats(double milliseconds, qint64 triangles);
    void showRenderError(const QString &message);

private:
    void createMenus();
    void createStatusBar();
    void setScenePath(const QString &path);
    QString dialogFolder() const;
    void warn(const QString &title, const QString &message);

    Viewport *m_viewport = nullptr;
    QAction *m_resetCameraAction = nullptr;
    QAction *m_lightMarkersAction = nullptr;
    QLabel *m_frameLabel = nullptr;
    QLabel *m_rendererLabel = nullptr;
    QString m_scenePath;
};

} // namespace phonglab
