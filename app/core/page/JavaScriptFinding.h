#pragma once
#include <QString>

namespace phonglab {

// One thing the page's JavaScript did, found in its capture: the half of
// the exercise no reading of the shaders can see (the normals it put in a
// VBO, the matrices and light it sent). The keys are an interface (JSON
// "page.javascript"): never renamed.
struct JavaScriptFinding {
    QString key;     // "normals-exact", "normal-matrix-transpose", ...
    QString subject; // the mesh file or the uniform it is about
    bool mistake = false;
    QString message; // a sentence, in the run's language
    QString where;   // the JavaScript call that sent it, "js/main.js:42"; may be empty
};

} // namespace phonglab
