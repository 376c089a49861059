// Shaders as WebGL projects hold them (core/project): in script
// elements of any type and id, hidden textareas, JavaScript template
// literals, concatenations and joined arrays, createTextNode, and files of
// their own; paired by the project's own calls, by names, or as the one pair
// left; every line where the file has it. What the page
// computes between pieces stands as a placeholder token, a student's own
// file named like a library is read, and a shader file that is in fact
// JavaScript is read as its strings.
#include "TestFiles.h"
#include "core/project/HtmlShaders.h"
#include "core/project/JsScanner.h"
#include "core/project/JsShaders.h"
#include "core/project/ProjectPrograms.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using phonglab::test::lineOf;

namespace {

constexpr char kPhongVertex[] =
    "attribute vec4 vPosition;\n"
    "attribute vec3 vNormal;\n"
    "uniform mat4 modelViewMatrix, projectionMatrix;\n"
    "uniform vec4 lightPosition;\n"
    "varying vec3 N, L;\n"
    "void main() {\n"
    "    N = vNormal; L = lightPosition.xyz;\n"
    "    gl_Position = projectionMatrix * modelViewMatrix * vPosition;\n"
    "}\n";
constexpr char kPhongFragment[] =
    "precision mediump float;\n"
    "uniform vec4 ambientProduct, diffuseProduct;\n"
    "varying vec3 N, L;\n"
    "void main() {\n"
    "    gl_FragColor = ambientProduct + diffuseProduct * max(dot(N, L), 0.0);\n"
    "}\n";

void write(const QString &path, const QByteArray &text)
{
    QVERIFY(test::writeTestFile(path, text));
}

const ProjectProgram *named(const Project &p, const QString &name)
{
    for (const ProjectProgram &program : p.programs)
        if (program.name == name)
            return &program;
    return nullptr;
}

// Angel & Shreiner: script elements, initShaders by id; a Gouraud pair
// beside the Phong pair, and an unlit grid of type "notjs".
QByteArray angelPage()
{
    return QByteArray("<!DOCTYPE html>\n<html><head>\n"
                      "<script id=\"vertex-shader\" type=\"x-shader/x-vertex\">\n")
        + kPhongVertex + "</script>\n<script id=\"fragment-shader\" type=\"x-shader/x-fragment\">\n"
        + kPhongFragment
        + "</script>\n"
          "<script id=\"gouraud-vshader\" type=\"x-shader/x-vertex\">\n"
        + kPhongVertex + "</script>\n<script id=\"gouraud-fshader\" type=\"x-shader/x-fragment\">\n"
        + kPhongFragment
        + "</script>\n"
          "<script id=\"grid-vs\" type=\"notjs\">attribute vec4 p; void main() { gl_Position = p; "
          "}</script>\n"
          "<script id=\"grid-fs\" type=\"notjs\">void main() { gl_FragColor = vec4(0.5); "
          "}</script>\n"
          "<script>\n"
          "  // initShaders(gl, \"commented\", \"out\") must not count\n"
          "  var re = /`[^`]*`/g; var s = \"`not a template`\";\n"
          "  program = initShaders(gl, \"vertex-shader\", \"fragment-shader\");\n"
          "  gouraud = initShaders(gl, 'gouraud-vshader', 'gouraud-fshader');\n"
          "  grid = initShaders(gl, 'grid-vs', 'grid-fs');\n"
          "</script></head><body></body></html>\n";
}

// The 1-based column of the first `needle` on its line of `text`; -1 when
// it is not there.
int columnOf(const QByteArray &text, const QByteArray &needle)
{
    const qsizetype at = text.indexOf(needle);
    return at < 0 ? -1 : int(at - text.lastIndexOf('\n', at));
}

// A script building its two stages from pieces, `expression` the page's
// computed value in the vertex stage's uniform array (as a `+` piece or a
// ${...}), paired by initShaderProgram.
QByteArray piecesScript(const QByteArray &declaration)
{
    return "// lights.js\n"
           "function sources(n) {\n"
           "  const vs =\n"
           "      'attribute vec4 aPosition;\\n' +\n"
        + declaration
        + "      'void main() {\\n' +\n"
          "      '  gl_Position = aPosition + vec4(lightPos[0], 0.0);\\n' +\n"
          "      '}\\n';\n"
          "  const fs = `precision mediump float;\n"
          "uniform vec3 lightColor;\n"
          "void main() { gl_FragColor = vec4(lightColor, 1.0); }\n"
          "`;\n"
          "  return initShaderProgram(gl, vs, fs);\n"
          "}\n";
}

// Bytes that no one writes by hand: one line of a library's minified code.
QByteArray minified(const QByteArray &code)
{
    QByteArray out = code;
    while (out.size() < 40 * 1024)
        out += "var a=function(b,c){return b*c+1};";
    return out + "\n";
}
} // namespace

class TestProjectShaders : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void scriptElementsPairedByTheirCall()
    {
        const QString page = m_dir.filePath(QStringLiteral("angel/index.html"));
        write(page, angelPage());
        const Project p = readProject(m_dir.filePath(QStringLiteral("angel")));
        QVERIFY2(p.error.isEmpty(), qPrintable(p.error));
        QStringList names;
        for (const ProjectProgram &program : p.programs)
            names << program.name;
        QCOMPARE(names,
                 (QStringList{QStringLiteral("gouraud"), QStringLiteral("grid"),
                              QStringLiteral("index")}));
        const ProjectProgram *phong = named(p, QStringLiteral("index"));
        const ProjectProgram *gouraud = named(p, QStringLiteral("gouraud"));
        const ProjectProgram *grid = named(p, QStringLiteral("grid"));
        QVERIFY(phong && gouraud && grid);
        QCOMPARE(phong->vertex.key, QStringLiteral("vertex-shader"));
        QCOMPARE(phong->fragment.key, QStringLiteral("fragment-shader"));
        QVERIFY(phong->lit && gouraud->lit);
        QVERIFY(!grid->lit);
        QCOMPARE(litPrograms(p).size(), std::size_t(2));
        QVERIFY(p.notes.join(QLatin1Char('\n')).contains(QStringLiteral("grid: not checked")));
        // Lines as in the page: the code's gl_Position line is the page's.
        const QByteArray html = angelPage();
        QCOMPARE(lineOf(phong->vertex.code, "gl_Position"), lineOf(html, "gl_Position"));
        QCOMPARE(phong->vertex.line, lineOf(html, "attribute vec4 vPosition"));
        QVERIFY(phong->vertex.writable);
        QString error;
        QVERIFY(!programNamed(p, QStringLiteral("nosuch"), &error));
        QVERIFY(error.contains(QStringLiteral("gouraud")));
    }

    // Opening shadedSphere2.html of a folder of Angel's pages
    // offers its own program first, not the folder's first.
    void thePageChosenChoosesItsProgram()
    {
        const QByteArray page =
            QByteArray("<!DOCTYPE html>\n<html><head>\n"
                       "<script id=\"vertex-shader\" type=\"x-shader/x-vertex\">\n")
            + kPhongVertex
            + "</script>\n<script id=\"fragment-shader\" type=\"x-shader/x-fragment\">\n"
            + kPhongFragment
            + "</script>\n<script>program = initShaders(gl, \"vertex-shader\", "
              "\"fragment-shader\");</script>\n</head></html>\n";
        for (const char *name : {"shadedSphere1", "shadedSphere2", "shadedSphere3"})
            write(m_dir.filePath(QStringLiteral("spheres/%1.html").arg(QLatin1String(name))), page);
        const Project p = readProject(m_dir.filePath(QStringLiteral("spheres")));
        const std::vector<const ProjectProgram *> lit = litPrograms(p);
        QVERIFY2(lit.size() == std::size_t(3), qPrintable(p.notes.join(u'\n') + p.error));
        const std::size_t chosen =
            programOfPage(lit, m_dir.filePath(QStringLiteral("spheres/shadedSphere2.html")));
        QCOMPARE(lit[chosen]->name, QStringLiteral("shadedSphere2"));
        QVERIFY(lit[chosen]->fragment.file.endsWith(QStringLiteral("shadedSphere2.html")));
        QCOMPARE(programOfPage(lit, QString()), std::size_t(0));
    }

    void templateLiteralsInAScriptFile()
    {
        // webglfundamentals: WebGL 2 sources in template literals of a .js
        // file, a program from both.
        const QByteArray js = "'use strict';\n"
                              "const vertexShaderSource = `#version 300 es\n"
                              "in vec4 a_position;\nuniform vec3 u_lightWorldPosition;\n"
                              "void main() {\n  gl_Position = a_position;\n}\n`;\n"
                              "const fragmentShaderSource = `#version 300 es\n"
                              "precision highp float;\nout vec4 outColor;\n"
                              "void main() {\n  outColor = vec4(1);\n}\n`;\n"
                              "const program = webglUtils.createProgramFromSources(gl, "
                              "[vertexShaderSource, fragmentShaderSource]);\n";
        write(m_dir.filePath(QStringLiteral("wgf/main.js")), js);
        write(m_dir.filePath(QStringLiteral("wgf/index.html")),
              "<html><body><canvas></canvas><script src=\"main.js\"></script></body></html>\n");
        const Project p = readProject(m_dir.filePath(QStringLiteral("wgf")));
        QCOMPARE(p.programs.size(), std::size_t(1));
        const ProjectProgram &program = p.programs.front();
        QCOMPARE(program.vertex.key, QStringLiteral("vertexShaderSource"));
        QVERIFY(program.lit);
        // #version stays the first text of the code; its line is the file's.
        QVERIFY(program.vertex.code.trimmed().startsWith("#version 300 es"));
        QCOMPARE(lineOf(program.vertex.code, "gl_Position"), lineOf(js, "gl_Position"));
        QCOMPARE(lineOf(program.fragment.code, "outColor ="), lineOf(js, "outColor ="));
        // The column too: the first line begins after the backtick.
        const QByteArray first = program.vertex.code.split('\n').at(program.vertex.line - 1);
        QCOMPARE(first.indexOf("#version"), js.split('\n').at(1).indexOf("#version"));
        QVERIFY(program.vertex.writable);
    }

    void inlineScriptConcatenationTextareaAndTextNode()
    {
        // MDN in an inline script; a concatenation; a textarea with &lt;;
        // createTextNode with a literal.
        const QByteArray html =
            "<html><body>\n"
            "<textarea id=\"fs\" style=\"display:none\">\n"
            "precision highp float; uniform vec3 lightColor;\n"
            "void main() { float x = 1.0; if (x &lt; 2.0) gl_FragColor = vec4(lightColor, 1.0); }\n"
            "</textarea>\n"
            "<script>\n"
            "var vs = 'attribute vec4 p;\\n' +\n"
            "         'void main() {\\n' +\n"
            "         '  gl_Position = p;\\n' +\n"
            "         '}\\n';\n"
            "const prog = initShaderProgram(gl, vs, document.getElementById('fs').value);\n"
            "var n = document.createTextNode(`void main() { gl_FragColor = vec4(0); }`);\n"
            "</script></body></html>\n";
        write(m_dir.filePath(QStringLiteral("mdn/page.html")), html);
        const Project p = readProject(m_dir.filePath(QStringLiteral("mdn/page.html")));
        QCOMPARE(p.programs.size(), std::size_t(1));
        const ProjectProgram &program = p.programs.front();
        QCOMPARE(program.vertex.key, QStringLiteral("vs"));
        QCOMPARE(program.fragment.key, QStringLiteral("fs"));
        QVERIFY(program.fragment.code.contains("x < 2.0")); // the reference read
        QVERIFY(program.fragment.writable);                 // &lt; read, written back the same
        QVERIFY(!program.vertex.writable);                  // several strings
        // Each piece on the line it is written on.
        QCOMPARE(lineOf(program.vertex.code, "gl_Position"), lineOf(html, "gl_Position"));
        QCOMPARE(lineOf(program.fragment.code, "lightColor;"), lineOf(html, "lightColor;"));
        // The text node's shader: no program takes it, and it is said.
        QVERIFY2(p.notes.join(QLatin1Char('\n')).contains(QStringLiteral("line ")),
                 qPrintable(p.notes.join(QLatin1Char('\n'))));
    }

    void threeJsMaterialAndFilesByStem()
    {
        const QByteArray html =
            "<script type=\"x-shader/x-vertex\" id=\"vertexShader\">varying vec3 vNormal;\n"
            "void main() { vNormal = normal; gl_Position = projectionMatrix * vec4(position, 1.0); "
            "}"
            "</script>\n"
            "<script type=\"x-shader/x-fragment\" id=\"fragmentShader\">uniform vec3 lightDir;\n"
            "varying vec3 vNormal; void main() { gl_FragColor = vec4(max(dot(vNormal, lightDir), "
            "0.0)); }"
            "</script>\n"
            "<script type=\"module\">\n"
            "const m = new THREE.ShaderMaterial({ uniforms: {},\n"
            "  vertexShader: document.getElementById('vertexShader').textContent,\n"
            "  fragmentShader: document.getElementById('fragmentShader').textContent });\n"
            "</script>\n";
        write(m_dir.filePath(QStringLiteral("three/index.html")), html);
        write(m_dir.filePath(QStringLiteral("three/shaders/phong_color.vert")), kPhongVertex);
        write(m_dir.filePath(QStringLiteral("three/shaders/phong_color.frag")), kPhongFragment);
        write(m_dir.filePath(QStringLiteral("three/main.js")),
              "fetch('shaders/phong_color.vert'); fetch('shaders/phong_color.frag');\n");
        const Project p = readProject(m_dir.filePath(QStringLiteral("three")));
        QCOMPARE(p.programs.size(), std::size_t(2));
        QVERIFY(named(p, QStringLiteral("phong_color")));
        const ProjectProgram *material = named(p, QStringLiteral("index"));
        QVERIFY(material);
        QCOMPARE(material->vertex.key, QStringLiteral("vertexShader"));
    }

    void linksOutOfTheProjectAreNotRead()
    {
        write(m_dir.filePath(QStringLiteral("secret.frag")), kPhongFragment);
        write(m_dir.filePath(QStringLiteral("linked/a.vert")), kPhongVertex);
        QVERIFY(QFile::link(m_dir.filePath(QStringLiteral("secret.frag")),
                            m_dir.filePath(QStringLiteral("linked/a.frag"))));
        const Project p = readProject(m_dir.filePath(QStringLiteral("linked")));
        QVERIFY(p.programs.empty());
        QVERIFY(p.notes.join(QLatin1Char('\n')).contains(QStringLiteral("a.frag: not read")));
    }

    void locatorReadsTheShaderAgain()
    {
        const QString page = m_dir.filePath(QStringLiteral("loc/index.html"));
        write(page, angelPage());
        QVERIFY(isShaderLocator(page + QStringLiteral("#fragment-shader")));
        QVERIFY(!isShaderLocator(page));
        const Result<ProjectShader> s = shaderAtLocator(page + QStringLiteral("#fragment-shader"));
        QVERIFY(s);
        QCOMPARE(s->stage, ShaderStage::Fragment);
        QVERIFY(!shaderAtLocator(page + QStringLiteral("#nosuch")));
    }

    void expressionsBetweenPiecesArePlaceholders_data()
    {
        QTest::addColumn<QByteArray>("declaration");
        QTest::addColumn<QByteArray>("expression"); // its first bytes in the file
        QTest::addColumn<QByteArray>("expected");   // what the shader's text holds there
        QTest::newRow("plus, this.num_lights")
            << QByteArray("      'uniform vec3 lightPos[' + this.num_lights + '];\\n' +\n")
            << QByteArray("this.num_lights") << QByteArray("uniform vec3 lightPos[NUM_LIGHTS];");
        QTest::newRow("plus, a call in parentheses")
            << QByteArray("      'uniform vec3 lightPos[' + String(lights.length) + '];\\n' +\n")
            << QByteArray("String(") << QByteArray("uniform vec3 lightPos[LIGHTS_LENGTH];");
        QTest::newRow("plus, a #define of the same name")
            << QByteArray("      \"#define N \" + n + \"\\n\" +\n"
                          "      'uniform vec3 lightPos[N];\\n' +\n")
            << QByteArray("n + \"") << QByteArray("#define N N_VALUE");
        QTest::newRow("template literal")
            << QByteArray("      `uniform vec3 lightPos[${this.numLights}];\n` +\n")
            << QByteArray("this.numLights}") << QByteArray("uniform vec3 lightPos[NUM_LIGHTS];");
    }

    void expressionsBetweenPiecesArePlaceholders()
    {
        QFETCH(QByteArray, declaration);
        QFETCH(QByteArray, expression);
        QFETCH(QByteArray, expected);
        const QByteArray js = piecesScript(declaration);
        const QString dir =
            m_dir.filePath(QStringLiteral("pieces/%1").arg(QTest::currentDataTag()));
        write(dir + QStringLiteral("/lights.js"), js);
        const Project p = readProject(dir);
        QVERIFY2(p.error.isEmpty(), qPrintable(p.error));
        QCOMPARE(p.programs.size(), std::size_t(1)); // paired by initShaderProgram
        const ProjectShader &vertex = p.programs.front().vertex;
        QCOMPARE(vertex.key, QStringLiteral("vs"));
        QCOMPARE(vertex.stage, ShaderStage::Vertex);
        QVERIFY2(vertex.text.contains(expected), vertex.text.constData());
        QVERIFY(!vertex.writable); // the page computes part of it
        // Every piece on the file's line; the placeholder on its expression's.
        QCOMPARE(lineOf(vertex.code, "gl_Position"), lineOf(js, "gl_Position"));
        QCOMPARE(lineOf(vertex.code, expected), lineOf(js, expression));
        QCOMPARE(lineOf(vertex.code, "void main"), lineOf(js, "void main"));
        // A line that starts with a piece starts at the piece's column.
        QCOMPARE(columnOf(vertex.code, "void main"), columnOf(js, "void main"));
        QCOMPARE(p.programs.front().fragment.key, QStringLiteral("fs"));
    }

    void placeholderNames_data()
    {
        QTest::addColumn<QByteArray>("expression");
        QTest::addColumn<QByteArray>("name");
        QTest::newRow("member") << QByteArray("this.num_lights") << QByteArray("NUM_LIGHTS");
        QTest::newRow("camelCase") << QByteArray(" this.numLights ") << QByteArray("NUM_LIGHTS");
        QTest::newRow("one letter") << QByteArray("n") << QByteArray("N");
        QTest::newRow("length") << QByteArray("scene.lights.length") << QByteArray("LIGHTS_LENGTH");
        QTest::newRow("conversion") << QByteArray("count.toFixed(1)") << QByteArray("COUNT");
        QTest::newRow("reserved GL_") << QByteArray("gl_lights") << QByteArray("JS_GL_LIGHTS");
        QTest::newRow("underscores") << QByteArray("__max__count_") << QByteArray("MAX_COUNT");
        QTest::newRow("no name") << QByteArray("(1 + 2)") << QByteArray("JS_VALUE");
    }

    void placeholderNames()
    {
        QFETCH(QByteArray, expression);
        QFETCH(QByteArray, name);
        QCOMPARE(jsPlaceholderName({expression.constData(), std::size_t(expression.size())}), name);
    }

    void templateLiteralsAreCutAtSubstitutions()
    {
        const std::string_view js = "`a\\${no}b${ {x: `}`}.x }c${n}`";
        const std::vector<JsToken> tokens = scanJs(js);
        QCOMPARE(tokens.size(), std::size_t(1));
        const JsTemplateParts t = jsTemplateParts(js, tokens.front());
        QCOMPARE(t.parts.size(), std::size_t(3));
        QCOMPARE(t.parts[0].value, QByteArray("a${no}b"));
        QCOMPARE(t.parts[1].value, QByteArray("c"));
        QCOMPARE(t.parts[2].value, QByteArray());
        QCOMPARE(js.substr(std::size_t(t.substitutions[1].first),
                           std::size_t(t.substitutions[1].second - t.substitutions[1].first)),
                 std::string_view("n"));
        // Unterminated: nothing known.
        const std::string_view open = "`a${b";
        QVERIFY(jsTemplateParts(open, scanJs(open).front()).parts.empty());
    }

    void aStudentsFileNamedLikeALibraryIsRead_data()
    {
        QTest::addColumn<QString>("fileName");
        QTest::newRow("Phong-Lib.js") << QStringLiteral("Phong-Lib.js");
        QTest::newRow("lighting-lib.js") << QStringLiteral("lighting-lib.js");
        QTest::newRow("shaderlib.js") << QStringLiteral("shaderlib.js");
    }

    void aStudentsFileNamedLikeALibraryIsRead()
    {
        QFETCH(QString, fileName);
        const QByteArray js = "var PhongLib = {};\n"
                              "PhongLib.vertexShader =\n"
                              "  'attribute vec4 vPosition;\\n' +\n"
                              "  'uniform vec4 lightPosition;\\n' +\n"
                              "  'void main() {\\n' +\n"
                              "  '  gl_Position = vPosition + lightPosition;\\n' +\n"
                              "  '}\\n';\n"
                              "PhongLib.fragmentShader =\n"
                              "  'precision mediump float;\\n' +\n"
                              "  'uniform vec4 diffuseProduct;\\n' +\n"
                              "  'void main() { gl_FragColor = diffuseProduct; }\\n';\n"
                              "PhongLib.program = function(gl) {\n"
                              "  return createProgram(gl, PhongLib.vertexShader, "
                              "PhongLib.fragmentShader);\n"
                              "};\n";
        const QString dir = m_dir.filePath(QStringLiteral("lib/") + fileName);
        write(dir + QLatin1Char('/') + fileName, js);
        write(dir + QStringLiteral("/index.html"),
              "<html><body><script src=\"" + fileName.toUtf8() + "\"></script></body></html>\n");
        const Project p = readProject(dir);
        QVERIFY2(p.error.isEmpty(), qPrintable(p.error));
        QCOMPARE(p.programs.size(), std::size_t(1));
        const ProjectProgram &program = p.programs.front();
        QCOMPARE(QFileInfo(program.vertex.file).fileName(), fileName);
        QCOMPARE(program.vertex.key, QStringLiteral("vertexShader"));
        QCOMPARE(program.fragment.key, QStringLiteral("fragmentShader"));
        QCOMPARE(program.fragment.stage, ShaderStage::Fragment);
        QVERIFY(program.lit);
        QCOMPARE(lineOf(program.vertex.code, "gl_Position"), lineOf(js, "gl_Position"));
        QCOMPARE(lineOf(program.fragment.code, "gl_FragColor"), lineOf(js, "gl_FragColor"));
        QCOMPARE(columnOf(program.vertex.code, "uniform"), columnOf(js, "uniform"));
    }

    void genuineLibrariesAreSkipped()
    {
        // The student's page: two programs, each paired by its stem.
        const QByteArray html = "<html><head>\n"
                                "<script id=\"phong-vs\" type=\"x-shader/x-vertex\">\n"
            + QByteArray(kPhongVertex)
            + "</script>\n<script id=\"phong-fs\" type=\"x-shader/x-fragment\">\n" + kPhongFragment
            + "</script>\n<script id=\"grid-vs\" type=\"x-shader/x-vertex\">attribute vec4 p;\n"
              "void main() { gl_Position = p; }</script>\n"
              "<script id=\"grid-fs\" type=\"x-shader/x-fragment\">precision mediump float;\n"
              "void main() { gl_FragColor = vec4(0.5); }</script>\n"
              "</head><body></body></html>\n";
        const QString dir = m_dir.filePath(QStringLiteral("libs"));
        write(dir + QStringLiteral("/index.html"), html);
        // A bundle by its name, with shaders of its own.
        const QByteArray bundleShader =
            "var s = 'uniform vec4 lightColor; void main() { gl_Position = vec4(lightColor); }';\n";
        write(dir + QStringLiteral("/js/three.module.js"), bundleShader);
        write(dir + QStringLiteral("/js/gl-matrix-min.js"), bundleShader);
        write(dir + QStringLiteral("/js/vendor.min.js"), bundleShader);
        // Minified, with no shader of its own but a call that would pair the
        // student's shaders wrongly were it read.
        const QByteArray calls = minified("initShaders(gl,\"phong-vs\",\"grid-fs\");");
        write(dir + QStringLiteral("/js/engine.js"), calls);
        const Project p = readProject(dir);
        QVERIFY2(p.error.isEmpty(), qPrintable(p.error));
        QCOMPARE(p.programs.size(), std::size_t(2));
        const ProjectProgram *phong = named(p, QStringLiteral("phong"));
        QVERIFY(phong);
        QCOMPARE(phong->fragment.key, QStringLiteral("phong-fs"));
        // No library shader left over for no program to take.
        QVERIFY2(!p.notes.join(QLatin1Char('\n')).contains(QStringLiteral("no program takes")),
                 qPrintable(p.notes.join(QLatin1Char('\n'))));
        // Given alone, a file is read, whatever it looks like.
        QCOMPARE(readProject(dir + QStringLiteral("/js/vendor.min.js")).error, QString());
    }

    void shaderFilesThatAreJavaScript_data()
    {
        QTest::addColumn<QString>("vertexFile");
        QTest::addColumn<QByteArray>("vertexJs");
        QTest::addColumn<QString>("fragmentFile");
        QTest::addColumn<QByteArray>("fragmentJs");
        QTest::newRow("var and const, .vert and .frag")
            << QStringLiteral("phong.vert")
            << (QByteArray("// Phong's vertex stage\nvar phongVS = `") + kPhongVertex + "`;\n")
            << QStringLiteral("phong.frag")
            << QByteArray("const phongFS = \"precision mediump float;\\n\" +\n"
                          "  \"uniform vec4 diffuseProduct;\\n\" +\n"
                          "  \"void main() { gl_FragColor = diffuseProduct; }\";\n");
        QTest::newRow("export and let, .vs and .fs")
            << QStringLiteral("phong.vs")
            << (QByteArray("/* Phong */\nexport const phongVS = `") + kPhongVertex + "`;\n")
            << QStringLiteral("phong.fs")
            << (QByteArray("let phongFS = `") + kPhongFragment + "`;\n");
        QTest::newRow(".glsl") << QStringLiteral("phong-vertex.glsl")
                               << (QByteArray("window.phongVS = `") + kPhongVertex + "`;\n")
                               << QStringLiteral("phong-fragment.glsl")
                               << (QByteArray("window.phongFS = `") + kPhongFragment + "`;\n");
    }

    void shaderFilesThatAreJavaScript()
    {
        QFETCH(QString, vertexFile);
        QFETCH(QByteArray, vertexJs);
        QFETCH(QString, fragmentFile);
        QFETCH(QByteArray, fragmentJs);
        const QString dir =
            m_dir.filePath(QStringLiteral("jsfiles/%1").arg(QTest::currentDataTag()));
        write(dir + QLatin1Char('/') + vertexFile, vertexJs);
        write(dir + QLatin1Char('/') + fragmentFile, fragmentJs);
        write(dir + QStringLiteral("/index.html"),
              "<html><body>\n<script src=\"" + vertexFile.toUtf8() + "\"></script>\n<script src=\""
                  + fragmentFile.toUtf8()
                  + "\"></script>\n<script>\nvar program = initShaders(gl, phongVS, phongFS);\n"
                    "</script></body></html>\n");
        QVERIFY(holdsShaderStrings(vertexJs));
        QVERIFY(!holdsShaderStrings(kPhongVertex)); // GLSL itself has no strings
        const Project p = readProject(dir);
        QVERIFY2(p.error.isEmpty(), qPrintable(p.error));
        QCOMPARE(p.programs.size(), std::size_t(1));
        const ProjectProgram &program = p.programs.front();
        // The strings, not the file's JavaScript as GLSL.
        QCOMPARE(program.vertex.key, QStringLiteral("phongVS"));
        QCOMPARE(program.fragment.key, QStringLiteral("phongFS"));
        QCOMPARE(QFileInfo(program.vertex.file).fileName(), vertexFile);
        QCOMPARE(QFileInfo(program.fragment.file).fileName(), fragmentFile);
        QCOMPARE(program.vertex.stage, ShaderStage::Vertex);
        QVERIFY(!program.vertex.code.contains("phongVS"));
        QVERIFY(program.vertex.text.startsWith("attribute vec4 vPosition;"));
        QCOMPARE(lineOf(program.vertex.code, "gl_Position"), lineOf(vertexJs, "gl_Position"));
        QCOMPARE(lineOf(program.fragment.code, "gl_FragColor"), lineOf(fragmentJs, "gl_FragColor"));
        QCOMPARE(columnOf(program.vertex.code, "attribute"), columnOf(vertexJs, "attribute"));
    }

    void scannerKnowsStringsTemplatesAndRegexes()
    {
        const std::string_view js =
            "a = b / c / d; r = /x`y/g; t = `a${ {x: `in`}.x }b`; s = '\\'';";
        const std::vector<JsToken> tokens = scanJs(js);
        int regexes = 0, templates = 0, strings = 0;
        for (const JsToken &t : tokens) {
            regexes += t.kind == JsTokenKind::Regex;
            templates += t.kind == JsTokenKind::Template;
            strings += t.kind == JsTokenKind::String;
        }
        QCOMPARE(regexes, 1);
        QCOMPARE(templates, 1); // the inner one is part of the outer
        QCOMPARE(strings, 1);
        const JsToken &last = tokens[tokens.size() - 2];
        QCOMPARE(jsStringValue(js, last).value, QByteArray("'"));
    }
};

QTEST_GUILESS_MAIN(TestProjectShaders)
#include "tst_projectshaders.moc"
