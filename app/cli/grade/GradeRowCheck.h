#pragma once
#include "GradeReferences.h"
#include "GradeRows.h"
#include "cli/check/GradedChild.h"

namespace phonglab::cli {

// A row of `grade` from its child's end: the child's findings read back,
// the image it drew checked against its scene's exact image, the verdict,
// and the heatmap written beside the image. Depends on nothing but its
// arguments (the row's own files under the out folder aside), so that rows
// are checked on several threads at once; a row that drew no image loses
// its image file.
void checkRow(GradeRow &row, const GradedChildEnd &end, const GradeResults &results,
              GradeReferences &references);

} // namespace phonglab::cli
