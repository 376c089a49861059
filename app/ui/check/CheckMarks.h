#pragma once
#include "CheckRunner.h"
#include "render/program/ShaderDiagnostic.h"

#include <vector>

namespace phonglab {

// Where the editor marks what the check found, as it marks a compile error:
// each mistake of the verdict on the lines that make it, with its rule; a
// uniform nothing places on its declaration. Per stage, 1-based lines of
// the text that was checked (CheckedFrame::outcome.stages).
struct CheckMarks {
    std::vector<ShaderDiagnostic> vertex;
    std::vector<ShaderDiagnostic> fragment;

    bool empty() const { return vertex.empty() && fragment.empty(); }
};

CheckMarks checkMarks(const CheckedFrame &result);

} // namespace phonglab
