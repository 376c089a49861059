#include "ProjectPrograms.h"

#include "HtmlShaders.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ProjectProgramsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ProjectPrograms)
};

namespace {

constexpr int kMaxProjectFiles = 2000;                   // a node_modules folder is not a project
constexpr qint64 kMaxProjectFileBytes = 8 * 1024 * 1024; // as shadersInFile reads
// Past this, a script with no shader in it is no student's (a library, a bundle).
constexpr qint64 kLargestStudentScript = 512 * 1024;

bool isScript(const QFileInfo &file)
{
    return isScriptFile(file.fileName());
}

// A library's bundle by its name: it holds its own shaders (three.module.js),
// not the student's. Only names no student's own file takes: a file named
// like a library of the student's (Phong-Lib.js, shaderlib.js) is read.
bool isKnownBundle(const QString &fileName)
{
    const QString name = fileName.toLower();
    if (name.endsWith(QLatin1String(".min.js")) || name.endsWith(QLatin1String(".min.mjs")))
        return true;
    for (const char *library : {"three.", "twgl", "webgl-utils", "gl-matrix"})
        if (name.startsWith(QLatin1String(library)))
            return true;
    return false;
}

bool isProjectFile(const QFileInfo &file)
{
    if (isKnownBundle(file.fileName()))
        return false;
    return isPageFile(file.fileName()) || isScript(file) || hasShaderFileSuffix(file.fileName());
}

// Minified: lines far longer than anyone writes by hand, all through the file.
bool looksMinified(const QByteArray &js)
{
    return js.size() >= 16 * 1024 && js.size() / (js.count('\n') + 1) > 500;
}

// A script read in a folder with no shader in it that is large or
// minified: a library's, whose own program calls (initShaders defined
// there) must not pair the student's shaders.
bool isLibraryByContent(const QFileInfo &file, const QByteArray &bytes)
{
    return isScript(file) && (bytes.size() > kLargestStudentScript || looksMinified(bytes));
}

// A file's shaders. A shader file that is in fact JavaScript (phong.vert
// holding `var phongVS = `...`;`) is read as the script it is, not as one
// GLSL text; shadersInText tells a file's kind by its suffix, so it reads
// it as a .js of that name, and the shaders keep the file's own path.
QStringList projectFiles(const QString &path, QStringList *notes)
{
    const QFileInfo info(path);
    if (info.isFile())
        return {info.absoluteFilePath()};
    const QString real = info.canonicalFilePath();
    QStringList files;
    QDirIterator it(info.absoluteFilePath(), QDir::Files | QDir::System | QDir::NoDotAndDotDot,
                    QDirIterator::Subdirectories);
    for (int seen = 0; it.hasNext() && seen < kMaxProjectFiles; ++seen) {
        const QFileInfo file(it.next());
        const QString relative = QDir(info.absoluteFilePath()).relativeFilePath(file.filePath());
        if (relative.contains(QLatin1String("node_modules/"))
            || relative.startsWith(QLatin1Char('.')) || relative.contains(QLatin1String("/."))
            || !isProjectFile(file))
            continue;
        if (file.isSymLink() || !file.canonicalFilePath().startsWith(real + QLatin1Char('/'))) {
            *notes << ProjectProgramsWords::tr("%1: not read (a symbolic link, or a path that "
                                               "leaves the project)")
                          .arg(relative);
            continue;
        }
        files << file.absoluteFilePath();
    }
    files.sort();
    return files;
}

// A name without its stage words: "phong-vs" and "phong-fs" are both
// "phong", "vertex-shader" and "fragment-shader" both "".
QString stemOf(const QString &name)
{
    QString n = QFileInfo(name).fileName();
    static const QRegularExpression shaderSuffix(
        QStringLiteral("\\.(%1)$").arg(shaderFileSuffixes().join(QLatin1Char('|'))),
        QRegularExpression::CaseInsensitiveOption);
    n.remove(shaderSuffix);
    // camelCase and separators into words
    n.replace(QRegularExpression(QStringLiteral("([a-z0-9])([A-Z])")), QStringLiteral("\\1_\\2"));
    QStringList kept;
    static const QStringList stageWords{
        QStringLiteral("vertex"),  QStringLiteral("fragment"),   QStringLiteral("vert"),
        QStringLiteral("frag"),    QStringLiteral("vs"),         QStringLiteral("fs"),
        QStringLiteral("vsh"),     QStringLiteral("fsh"),        QStringLiteral("shader"),
        QStringLiteral("source"),  QStringLiteral("src"),        QStringLiteral("glsl"),
        QStringLiteral("v"),       QStringLiteral("f"),          QStringLiteral("x"),
        QStringLiteral("text"),    QStringLiteral("code"),       QStringLiteral("pixel"),
        QStringLiteral("3d"),      QStringLiteral("2d"),         QStringLiteral("vshader"),
        QStringLiteral("fshader"), QStringLiteral("vertshader"), QStringLiteral("fragshader")};
    for (const QString &word :
         n.split(QRegularExpression(QStringLiteral("[^A-Za-z0-9]+")), Qt::SkipEmptyParts))
        if (!stageWords.contains(word.toLower()))
            kept << word.toLower();
    return kept.join(QLatin1Char('_'));
}

bool mentionsLight(const QByteArray &code)
{
    const QByteArray lower = code.toLower();
    for (const char *word : {"light", "ambientproduct", "diffuseproduct", "specularproduct",
                             "shininess", "lambert", "phong"})
        if (lower.contains(word))
            return true;
    return false;
}

// The shader a call's reference names: an id of the calling page first
// (each of Angel's pages in one folder has its own "vertex-shader"), then
// of any file (a script's call names the ids of the page that loads it).
int resolve(const std::vector<ProjectShader> &shaders, const JsShaderRef &ref, const QString &file)
{
    if (!ref.literalAt && !ref.name.isEmpty())
        for (std::size_t i = 0; i < shaders.size(); ++i)
            if (shaders[i].file == file && shaders[i].key == ref.name)
                return int(i);
    for (std::size_t i = 0; i < shaders.size(); ++i) {
        const ProjectShader &s = shaders[i];
        if (ref.literalAt) {
            if (s.file == file && s.begin <= *ref.literalAt
                && *ref.literalAt < std::max(s.end, s.begin + 1))
                return int(i);
            continue;
        }
        if (ref.name.isEmpty())
            continue;
        // By id or variable; a file by the end of its path ("shaders/phong.vert").
        if (s.key == ref.name
            || (QFileInfo(s.file).fileName() == s.key
                && QDir::fromNativeSeparators(s.file).endsWith(QLatin1Char('/') + ref.name)))
            return int(i);
    }
    for (std::size_t i = 0; i < shaders.size(); ++i) // a file named by its file name alone
        if (QFileInfo(shaders[i].file).fileName() == QFileInfo(ref.name).fileName()
            && QFileInfo(shaders[i].file).fileName() == shaders[i].key)
            return int(i);
    return -1;
}

QString programName(const ProjectShader &vertex, const ProjectShader &fragment)
{
    const QString v = stemOf(vertex.key);
    const QString f = stemOf(fragment.key);
    if (!v.isEmpty() && v == f)
        return v;
    if (!f.isEmpty() && v.isEmpty())
        return f;
    if (!v.isEmpty() && f.isEmpty())
        return v;
    if (!v.isEmpty())
        return v + QLatin1Char('+') + f;
    return QFileInfo(fragment.file).completeBaseName();
}

// The shaders of the project's files into `shaders`; the files read (a
// library's by its content left out), whose calls pair them.
QStringList readProjectFiles(const QString &path, QStringList *notes,
                             std::vector<ProjectShader> *shaders)
{
    const bool folder = QFileInfo(path).isDir();
    QStringList read;
    for (const QString &file : projectFiles(path, notes)) {
        QFile f(file);
        if (f.size() > kMaxProjectFileBytes || !f.open(QIODevice::ReadOnly))
            continue;
        const QByteArray bytes = f.readAll();
        std::vector<ProjectShader> found = shadersInText(file, bytes);
        if (found.empty() && folder && isLibraryByContent(QFileInfo(file), bytes))
            continue;
        for (ProjectShader &s : found)
            shaders->push_back(std::move(s));
        read << file;
    }
    return read;
}

// Pairs the shaders into programs, each shader into one program at most, by
// ever weaker evidence: the project's own calls, then stems, then what is left.
struct ShaderPairing {
    const std::vector<ProjectShader> &shaders;
    std::vector<ProjectProgram> &programs;
    std::vector<bool> taken = std::vector<bool>(shaders.size(), false);

    // Makes a program of vertex shader v and fragment shader f where both
    // are shaders of their stage that no program has taken.
    void pair(int v, int f)
    {
        if (v < 0 || f < 0 || v == f || taken[std::size_t(v)] || taken[std::size_t(f)]
            || shaders[std::size_t(v)].stage != ShaderStage::Vertex
            || shaders[std::size_t(f)].stage != ShaderStage::Fragment)
            return;
        taken[std::size_t(v)] = taken[std::size_t(f)] = true;
        ProjectProgram program;
        program.vertex = shaders[std::size_t(v)];
        program.fragment = shaders[std::size_t(f)];
        program.name = programName(program.vertex, program.fragment);
        program.lit = mentionsLight(program.vertex.code) || mentionsLight(program.fragment.code);
        programs.push_back(std::move(program));
    }

    // 1. The project's own calls.
    void pairByCalls(const QStringList &files)
    {
        for (const QString &file : files)
            for (const JsProgramCall &call : programCallsInFile(file))
                pair(resolve(shaders, call.vertex, file), resolve(shaders, call.fragment, file));
    }

    // 2. Names that differ only in a stage word (non-empty stems).
    void pairByStems()
    {
        for (std::size_t v = 0; v < shaders.size(); ++v)
            for (std::size_t f = 0; f < shaders.size(); ++f)
                if (!taken[v] && !taken[f] && !stemOf(shaders[v].key).isEmpty()
                    && stemOf(shaders[v].key) == stemOf(shaders[f].key))
                    pair(int(v), int(f));
    }

    // 3. The one vertex and one fragment shader left.
    void pairTheLastTwo()
    {
        std::vector<int> vertices, fragments;
        for (std::size_t i = 0; i < shaders.size(); ++i)
            if (!taken[i])
                (shaders[i].stage == ShaderStage::Vertex ? vertices : fragments).push_back(int(i));
        if (vertices.size() == 1 && fragments.size() == 1)
            pair(vertices.front(), fragments.front());
    }

    void noteUntaken(QStringList &notes) const
    {
        for (std::size_t i = 0; i < shaders.size(); ++i)
            if (!taken[i])
                notes << ProjectProgramsWords::tr("%1 (%2): a %3 shader no program takes")
                             .arg(QFileInfo(shaders[i].file).fileName(), shaders[i].key,
                                  shaders[i].stage == ShaderStage::Vertex
                                      ? ProjectProgramsWords::tr("vertex")
                                      : ProjectProgramsWords::tr("fragment"));
    }
};

// Unique names, in a stable order.
void sortAndNameUniquely(std::vector<ProjectProgram> &programs)
{
    std::stable_sort(
        programs.begin(), programs.end(),
        [](const ProjectProgram &a, const ProjectProgram &b) { return a.name < b.name; });
    for (std::size_t i = 1; i < programs.size(); ++i)
        if (programs[i].name == programs[i - 1].name)
            programs[i].name += QStringLiteral("-%1").arg(i + 1);
}

} // namespace

Project readProject(const QString &path)
{
    Project project;
    project.path = path;
    if (!QFileInfo::exists(path)) {
        project.error = ProjectProgramsWords::tr("%1: no such file or folder").arg(path);
        return project;
    }
    std::vector<ProjectShader> shaders;
    const QStringList files = readProjectFiles(path, &project.notes, &shaders);
    ShaderPairing pairing{shaders, project.programs};
    pairing.pairByCalls(files);
    pairing.pairByStems();
    pairing.pairTheLastTwo();
    pairing.noteUntaken(project.notes);
    sortAndNameUniquely(project.programs);
    for (const ProjectProgram &p : project.programs)
        if (!p.lit)
            project.notes << ProjectProgramsWords::tr(
                                 "%1: not checked, it lights nothing (no light, "
                                 "material product or shininess in it)")
                                 .arg(p.name);
    if (shaders.empty())
        project.error = ProjectProgramsWords::tr(
                            "%1: no shader found (no <script> or <textarea> with one, no string "
                            "in the JavaScript, no .vert/.frag/.glsl file)")
                            .arg(path);
    return project;
}

std::vector<const ProjectProgram *> litPrograms(const Project &project)
{
    std::vector<const ProjectProgram *> lit;
    for (const ProjectProgram &p : project.programs)
        if (p.lit)
            lit.push_back(&p);
    return lit;
}

std::size_t programOfPage(const std::vector<const ProjectProgram *> &programs, const QString &page)
{
    if (page.isEmpty())
        return 0;
    const QFileInfo pageFile(page);
    const auto inPage = [&](const ProjectShader &s) {
        return QFileInfo(s.file).canonicalFilePath() == pageFile.canonicalFilePath();
    };
    for (std::size_t i = 0; i < programs.size(); ++i)
        if (inPage(programs[i]->vertex) || inPage(programs[i]->fragment))
            return i;
    for (std::size_t i = 0; i < programs.size(); ++i)
        if (programs[i]->name == pageFile.completeBaseName())
            return i;
    return 0;
}

const ProjectProgram *programNamed(const Project &project, const QString &name, QString *error)
{
    QStringList names;
    for (const ProjectProgram &p : project.programs) {
        if (p.name == name)
            return &p;
        names << p.name;
    }
    *error = ProjectProgramsWords::tr("%1: no program named %2 (there are: %3)")
                 .arg(project.path, name,
                      names.isEmpty() ? QStringLiteral("none") : names.join(QStringLiteral(", ")));
    return nullptr;
}

} // namespace phonglab

namespace phonglab {

Result<ProjectProgram> chooseProgram(const Project &project, const QString &name)
{
    if (!project.error.isEmpty())
        return fail(project.error);
    if (!name.isEmpty()) {
        QString error;
        if (const ProjectProgram *named = programNamed(project, name, &error))
            return *named;
        return fail(error);
    }
    const std::vector<const ProjectProgram *> lit = litPrograms(project);
    if (lit.size() == 1)
        return *lit.front();
    if (lit.empty())
        return fail(ProjectProgramsWords::tr("%1: no program that lights anything (%2)")
                        .arg(project.path, project.notes.join(QStringLiteral("; "))));
    QStringList names;
    for (const ProjectProgram *p : lit)
        names << p->name;
    return fail(ProjectProgramsWords::tr("%1: %2 programs light the scene (%3); choose one")
                    .arg(project.path)
                    .arg(lit.size())
                    .arg(names.join(QStringLiteral(", "))));
}

} // namespace phonglab
