// Save into the page or script a shader came from (
// core/project/ProjectSave): only the shader's bytes change, escaped as
// their container escapes them, and read back they are the text saved; a
// shader built from several strings is refused with Save As as the way out.
#include "core/project/ProjectSave.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;

namespace {

QByteArray saveAndCheck(const QString &path, const QByteArray &file, const QString &key,
                        const QByteArray &newText)
{
    const Result<ProjectShader> shader = shaderAtLocator(path + QLatin1Char('#') + key);
    if (!shader) {
        QTest::qFail(qPrintable(shader.error()), __FILE__, __LINE__);
        return {};
    }
    // Unchanged: the very same bytes.
    const Result<QByteArray> same = withShaderText(file, *shader, shader->text);
    if (!same || *same != file) {
        QTest::qFail("saving the text unchanged changed the file", __FILE__, __LINE__);
        return {};
    }
    const Result<QByteArray> saved = withShaderText(file, *shader, newText);
    if (!saved) {
        QTest::qFail(qPrintable(saved.error()), __FILE__, __LINE__);
        return {};
    }
    // Every byte before and after the shader's stays.
    if (!saved->startsWith(file.left(shader->begin)) || !saved->endsWith(file.mid(shader->end)))
        QTest::qFail("bytes outside the shader changed", __FILE__, __LINE__);
    return *saved;
}

void write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

} // namespace

class TestProjectSave : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void intoAScriptElementAndATextarea()
    {
        const QByteArray page =
            "<html><head>\n<script id=\"vs\" type=\"x-shader/x-vertex\">\n"
            "attribute vec4 p; void main() { gl_Position = p; }\n</script>\n"
            "<textarea id=\"fs\" hidden>precision highp float;\n"
            "void main() { if (1.0 &lt; 2.0 &amp;&amp; true) gl_FragColor = vec4(1); }\n"
            "</textarea>\n</head></html>\n";
        const QString path = m_dir.filePath(QStringLiteral("page.html"));
        write(path, page);
        const QByteArray vertex = "attribute vec4 p;\nvoid main() { gl_Position = 2.0 * p; }\n";
        const QByteArray saved = saveAndCheck(path, page, QStringLiteral("vs"), vertex);
        write(path, saved);
        QCOMPARE(shaderAtLocator(path + QStringLiteral("#vs"))->text, vertex);
        // The textarea's & and < go back as references; read back, the text.
        const QByteArray fragment = "precision highp float;\nvoid main() { if (0.5 < 2.0 && true) "
                                    "gl_FragColor = vec4(0); }\n";
        const QByteArray again = saveAndCheck(path, saved, QStringLiteral("fs"), fragment);
        QVERIFY(again.contains("0.5 &lt; 2.0 &amp;&amp; true"));
        write(path, again);
        QCOMPARE(shaderAtLocator(path + QStringLiteral("#fs"))->text, fragment);
    }

    void intoATemplateLiteralKeepingItsEscapes()
    {
        // A backtick and a ${ in a comment, escaped as JavaScript needs.
        const QByteArray js = "const vsSource = `attribute vec4 p; // the \\`p\\` of \\${name}\n"
                              "void main() { gl_Position = p; }\n`;\nconst other = 1;\n";
        const QString path = m_dir.filePath(QStringLiteral("main.js"));
        write(path, js);
        const Result<ProjectShader> before = shaderAtLocator(path + QStringLiteral("#vsSource"));
        QVERIFY(before);
        QVERIFY(before->writable);
        QVERIFY(before->text.contains("the `p` of ${name}"));
        const QByteArray edited = before->text + "// and a \\ and a ` more\n";
        const QByteArray saved = saveAndCheck(path, js, QStringLiteral("vsSource"), edited);
        QVERIFY(saved.contains("// and a \\\\ and a \\` more"));
        write(path, saved);
        QCOMPARE(shaderAtLocator(path + QStringLiteral("#vsSource"))->text, edited);
    }

    void piecesAreNotWrittenBack()
    {
        const QByteArray js = "var fs = 'precision highp float;\\n' +\n"
                              "  'void main() { gl_FragColor = vec4(1); }\\n';\n";
        const QString path = m_dir.filePath(QStringLiteral("pieces.js"));
        write(path, js);
        const Result<ProjectShader> shader = shaderAtLocator(path + QStringLiteral("#fs"));
        QVERIFY(shader);
        QVERIFY(!shader->writable);
        const Result<QByteArray> saved = withShaderText(js, *shader, shader->text);
        QVERIFY(!saved);
        QVERIFY2(saved.error().contains(QStringLiteral("Save As")), qPrintable(saved.error()));
    }
};

QTEST_GUILESS_MAIN(TestProjectSave)
#include "tst_projectsave.moc"
