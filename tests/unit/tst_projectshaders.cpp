// Shaders as WebGL projects hold them (issue 42, A; core/project): in script
// elements of any type and id, hidden textareas, JavaScript template
// literals, concatenations and joined arrays, createTextNode, and files of
// their own; paired by the project's own calls, by names, or as the one pair
// left; every line where the file has it.
#include "TestFiles.h"
#include "core/project/JsScanner.h"
#include "core/project/ProjectPrograms.h"

#include <QDir>
#include <QFile>
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
        QCOMPARE(s->stage, ProjectStage::Fragment);
        QVERIFY(!shaderAtLocator(page + QStringLiteral("#nosuch")));
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
