#pragma once
#include <QString>
#include <QStringList>

namespace phonglab {

// What the window's command line asks for: `phonglab [FILE...]` opens a
// scene or meshes; `phonglab SCENE.json --vertex FILE --fragment FILE` opens
// a scene with a student's shaders; `phonglab SCENE.json
// --project PATH [--program NAME]` with a WebGL project's. Qt's own
// options are gone by now (QApplication takes them).
struct GuiArguments {
    QStringList files;
    QString vertexShader;   // --vertex FILE
    QString fragmentShader; // --fragment FILE
    QString project;        // --project PATH: a WebGL project's page, script or folder
    QString program;        // --program NAME: which of its programs
    QString error;          // a usage error, in a sentence; empty when none

    bool hasShaders() const
    {
        return !vertexShader.isEmpty() || !fragmentShader.isEmpty() || !project.isEmpty();
    }
};

// `arguments` without the program's name.
GuiArguments parseGuiArguments(const QStringList &arguments);

} // namespace phonglab
