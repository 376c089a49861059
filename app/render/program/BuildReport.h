#pragma once
#include "ShaderDiagnostic.h"

#include <QStringList>
#include <vector>

namespace phonglab {

// What building a program produced: success or not, and every diagnostic
// (errors and warnings) located in the user's files.
struct BuildReport {
    bool ok = false;
    std::vector<ShaderDiagnostic> diagnostics;

    bool hasErrors() const;
    QStringList formatted() const; // one "FILE:LINE:COL: error: MSG" per entry
    QString errorSummary() const;  // formatted() joined by newlines
};

} // namespace phonglab
