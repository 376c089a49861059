#pragma once
#include <QString>
#include <QStringList>

namespace phonglab {

// How the course's page is run for this scene (the scene's "page": check
// --page, grade --pages, the window's Run the Page), stated once by a
// teacher for the starter so that no student's run needs them on the
// command line. Paths as written, relative to the scene file.
struct PageSettings {
    QStringList steps;     // "select #shading=phong", "click #btnSphere", in order
    QStringList libraries; // the course's starter files (Common/, webgl-utils, gl-matrix)
    QString meshes;        // the folder of the course's meshes the normals are compared with
    int frame = 0;         // the frame captured; 0: the default (5)

    bool empty() const
    {
        return steps.isEmpty() && libraries.isEmpty() && meshes.isEmpty() && frame == 0;
    }
    bool operator==(const PageSettings &) const = default;
};

} // namespace phonglab
