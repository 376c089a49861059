#pragma once
#include "core/scene/Scene.h"

class QComboBox;

namespace phonglab {

// Fills a per-object selector ("1: tree.obj", ...) for the docks that edit
// one object at a time, keeping the current choice when it still exists.
void fillObjectChoice(QComboBox *combo, const Scene &scene);

} // namespace phonglab
