#pragma once

namespace phonglab::cli {

// phonglab grade SUBMISSIONS --scene FILE [--scene FILE ...] [--out DIR]
//                [--jobs N] [--timeout SECONDS] [--memory MIB] [--size WxH]
//                [--tolerance STEPS] [--bind NAME=MEANING ...]
//                [--equation slide|guarded]
// Checks every submission (a subfolder of SUBMISSIONS) against every scene,
// each in a child process of its own, and writes grades.csv, grades.json
// and report.html into DIR. Exit 0 when every submission got a verdict
// (whatever it is), 1 when the run could not complete, 2 on wrong arguments.
int runGrade(int argc, char **argv);

} // namespace phonglab::cli
