#pragma once
#include "ProjectShader.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace phonglab {

// A WebGL project's programs: its shaders paired as its own calls pair them
// (initShaders, createProgramFromScripts, ShaderMaterial, ...), else by
// names that differ only in a stage word (phong.vert + phong.frag,
// "phong-vs" + "phong-fs"), else the one vertex and one fragment shader
// left.

struct ProjectProgram {
    QString name; // the ids' or file names' common stem; the page's name where they have none
    ProjectShader vertex;
    ProjectShader fragment;
    // Whether it lights anything: a program that names no light, no
    // material product and no shininess (a grid, a skybox) is not checked.
    bool lit = true;
};

struct Project {
    QString path; // a file or a folder, as given
    std::vector<ProjectProgram> programs;
    // Shaders no program takes, unlit programs skipped, files not read.
    QStringList notes;
    QString error; // nothing could be read at all
};

// Reads a project: one page or script, or a folder (its .html, .js and
// shader files, below it too; links and paths leaving it are not read).
// In a folder, a library's bundle is not read: by its name (*.min.js,
// three.*, twgl*, webgl-utils*, gl-matrix*), or a script with no shader
// string in it that is minified or far larger than a student's. A shader
// file that is JavaScript (`var phongVS = `...`;` in phong.vert) is read as
// its strings.
Project readProject(const QString &path);

// The lit programs, or the one named `name` (error: none such, with the names there are).
std::vector<const ProjectProgram *> litPrograms(const Project &project);
// Of `programs`, the one the page `page` holds or loads: its shaders are in
// that file, else its name is the page's (a folder of Angel's pages, each
// with its program). 0 where none is, or no page was named.
std::size_t programOfPage(const std::vector<const ProjectProgram *> &programs, const QString &page);
const ProjectProgram *programNamed(const Project &project, const QString &name, QString *error);
// The program to check or edit: the one named `name`, else the one that
// lights. An error where the project cannot be read, has no such program,
// none that lights, or several (named: the caller says how to choose).
Result<ProjectProgram> chooseProgram(const Project &project, const QString &name);

} // namespace phonglab
