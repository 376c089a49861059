#pragma once
#include <QObject>

namespace phonglab {

class ShaderDock;

// The dialogs in front of the Shaders dock's Save and Save As: the file
// chooser, and what a failed save says. The dock shows none itself, so
// tests drive its save() and saveAs() without one; its Open… is the File
// menu's (one way to open shaders, whichever button starts it).
class ShaderFileDialogs : public QObject
{
    Q_OBJECT

public:
    // Answers the dock's saveRequested() and saveAsRequested(); a child of it.
    explicit ShaderFileDialogs(ShaderDock *dock);

    void saveCurrent();
    void chooseAndSaveAsCurrent();

private:
    void warn(const QString &message);

    ShaderDock *m_dock = nullptr;
};

} // namespace phonglab
