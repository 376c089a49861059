#include "ProgramSynopsis.h"

#include <QCoreApplication>

namespace phonglab {

namespace {
struct SynopsisWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ProgramSynopsis)
};
} // namespace

QString programSynopsis()
{
    return SynopsisWords::tr(
        "usage: phonglab [SCENE.json | MESH...]  start the editor on a scene or mesh files\n"
        "                                        (.obj .ply .off .stl .om; the default scene "
        "when none given)\n"
        "       phonglab SCENE.json --vertex FILE --fragment FILE\n"
        "                                        the editor on a scene with these shaders (either "
        "one alone\n"
        "                                        keeps the scene's other stage)\n"
        "       phonglab <command> [options]     run a command without a window");
}

} // namespace phonglab
