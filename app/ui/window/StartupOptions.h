#pragma once
#include "ui/shaders/ShaderRecovery.h"

#include <QString>

namespace phonglab {

// What the environment says when the window starts, read in one place: the
// overrides a user or a benchmark may set and the hooks the tests use. The
// window is built from these; nothing below it reads the environment for
// them again.
struct StartupOptions {
    // $PHONGLAB_RECOVERY_ANSWER=restore|discard: answers the crash-recovery
    // question without a dialog (tests, scripts).
    ShaderRecovery::Answer recoveryAnswer = ShaderRecovery::Answer::Ask;
    // $PHONGLAB_PRESENT_ON_GUI_THREAD set: frames are presented on the GUI
    // thread (the benchmark's comparison; drivers without threaded GL do so
    // anyway).
    bool presentOnGuiThread = false;
    // $PHONGLAB_DOC_DIR: searched first for the documentation.
    QString documentationFolder;
    // $PHONGLAB_TEST_TYPE_AFTER_START=TEXT: typed into the fragment editor once
    // GL is up, and journaled at once (the crash-recovery test kills the
    // process after it).
    QString typeAfterStart;

    static StartupOptions fromEnvironment();
};

} // namespace phonglab
