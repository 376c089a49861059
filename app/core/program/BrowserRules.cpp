#include "core/program/BrowserRules.h"

#include "core/program/GlslTokens.h"
#include "core/program/ShaderDialect.h"

#include <algorithm>
#include <optional>
#include <string_view>

namespace phonglab {

int BrowserRewrite::sourceColumn(int line, int column) const
{
    int shift = 0;
    for (const SourceInsertion &at : insertions) {
        if (at.line != line)
            continue;
        const int start = at.column + shift;
        if (column < start)
            break;
        if (column < start + int(at.text.size()))
            return at.column;
        shift += int(at.text.size());
    }
    return column - shift;
}

namespace {

using namespace glsl;

// A variable's type and array size as its declaration gives them.
struct Declared {
    std::string_view type;
    int name = -1;      // its token; -1 for a built-in output, declared by no line
    int sizeBegin = -1; // the array size's tokens, [sizeBegin, sizeEnd); -1: no array
    int sizeEnd = -1;
    std::string_view builtIn = {}; // gl_Position, gl_FragColor
};

struct Member {
    std::string_view type;
    std::string_view arraySize; // a literal, or empty where the member is no array
    bool sizeIsLiteral = true;
};

struct StructType {
    std::string_view name;
    std::vector<Member> members;
};

// Bounds that keep arbitrary bytes from exhausting the time: a longer
// shader, or one deeper in structs, is handed on unchanged.
constexpr std::size_t kMaxTokens = 400000;
constexpr int kMaxStructDepth = 8;

class Rewriter
{
public:
    Rewriter(const QByteArray &code, ShaderStage stage)
        : m_code(code)
        , m_stage(stage)
        , m_es100(shaderDialectOf(code) == ShaderDialect::Es100)
        , m_tokens(tokenize(code, m_macroWords))
        , m_n(int(m_tokens.size()))
    {
    }

    BrowserRewrite run();

private:
    std::string_view text(int i) const { return i >= 0 && i < m_n ? m_tokens[i].text : ""; }
    bool is(int i, std::string_view t) const { return text(i) == t; }
    int closeOf(int i) const { return i >= 0 && i < m_n && m_partner[i] >= 0 ? m_partner[i] : m_n; }
    int skipBrackets(int i) const
    {
        return oneOf(text(i), {"(", "[", "{"}) ? closeOf(i) + 1 : i + 1;
    }

    void topLevel();
    int globalDeclaration(int begin, int end);
    void function(int open, int body);
    void body(int open, int close);
    int localDeclaration(int begin, int close);
    int readStruct(int structWord);
    const StructType *structNamed(std::string_view name) const;
    std::string_view nameOf(const Declared &d) const
    {
        return d.name >= 0 ? text(d.name) : d.builtIn;
    }
    bool isType(std::string_view word) const { return isTypeName(word) || structNamed(word); }
    int declarators(int type, int end, std::vector<Declared> &unset) const;

    std::optional<QByteArray> zeroOf(std::string_view type, int depth = 0) const;
    std::optional<QByteArray> zeroing(const Declared &d) const;
    void insertAfter(int token, const QByteArray &text);
    void zeroAtDeclaration(const Declared &d, int semicolon);
    void noteZeroed(const Declared &d);
    void zeroAtEntry(int open, const std::vector<Declared> &variables);

    const QByteArray &m_code;
    ShaderStage m_stage;
    bool m_es100 = false;
    std::vector<std::string_view> m_macroWords;
    std::vector<Token> m_tokens;
    int m_n = 0;
    std::vector<int> m_partner;
    std::vector<StructType> m_structs;
    std::vector<Declared> m_globalsAtEntry; // outputs, and global arrays: zeroed as main() starts
    int m_mainBody = -1;
    BrowserRewrite m_out;
};

const StructType *Rewriter::structNamed(std::string_view name) const
{
    for (const StructType &s : m_structs)
        if (s.name == name)
            return &s;
    return nullptr;
}

// `struct NAME { TYPE member[SIZE], ...; ... }`: its members, for the
// constructor that zeroes it. Returns the token after the closing brace.
int Rewriter::readStruct(int structWord)
{
    if (structWord + 2 >= m_n)
        return m_n;
    const int open = structWord + 2;
    if (!is(open, "{") || !m_tokens[structWord + 1].word)
        return skipBrackets(structWord + 1);
    StructType s{text(structWord + 1), {}};
    const int close = closeOf(open);
    for (int i = open + 1; i < close;) {
        int type = i;
        while (isQualifier(text(type)))
            ++type;
        int k = type + 1;
        for (; k < close && !is(k, ";"); k = skipBrackets(k)) {
            if (!m_tokens[k].word)
                continue;
            Member m{text(type), {}, true};
            if (is(k + 1, "[")) {
                const int end = closeOf(k + 1);
                m.arraySize = end == k + 3 ? text(k + 2) : std::string_view("?");
                m.sizeIsLiteral = end == k + 3 && isDigit(text(k + 2)[0]);
            }
            s.members.push_back(m);
        }
        i = k + 1;
    }
    m_structs.push_back(s);
    return close + 1;
}

// The declarators of one declaration from `type` to its `;` at `end`: those
// without a value go to `unset`. Returns the number of declarators, 0 where
// this is no declaration after all (a call, a prototype).
int Rewriter::declarators(int type, int end, std::vector<Declared> &unset) const
{
    int at = type + 1;
    int typeSizeBegin = -1;
    int typeSizeEnd = -1;
    if (is(at, "[")) { // GLSL ES 3.00's `float[3] a;`
        typeSizeBegin = at + 1;
        typeSizeEnd = closeOf(at);
        at = typeSizeEnd + 1;
    }
    int count = 0;
    while (at < end) {
        if (!m_tokens[at].word || isKeyword(text(at)))
            return 0;
        Declared d{text(type), at, typeSizeBegin, typeSizeEnd};
        int next = at + 1;
        if (is(next, "[")) {
            d.sizeBegin = next + 1;
            d.sizeEnd = closeOf(next);
            next = d.sizeEnd + 1;
        }
        if (is(next, "("))
            return 0; // a function's prototype or a call
        if (is(next, "=")) {
            while (next < end && !is(next, ","))
                next = skipBrackets(next);
        } else {
            unset.push_back(d);
        }
        ++count;
        if (next >= end)
            break;
        if (!is(next, ","))
            return 0;
        at = next + 1;
    }
    return count;
}

std::optional<QByteArray> Rewriter::zeroOf(std::string_view type, int depth) const
{
    const QByteArray t(type.data(), qsizetype(type.size()));
    if (t == "float")
        return QByteArray("0.0");
    if (t == "int")
        return QByteArray("0");
    if (t == "uint")
        return QByteArray("0u");
    if (t == "bool")
        return QByteArray("false");
    if (isTypeName(type) && !t.startsWith('d')) {
        const char kind = t[0];
        const QByteArray value = kind == 'i' ? "0"
            : kind == 'u'                    ? "0u"
            : kind == 'b'                    ? "false"
                                             : "0.0";
        return t + '(' + value + ')';
    }
    const StructType *s = structNamed(type);
    if (!s || depth > kMaxStructDepth)
        return std::nullopt;
    QByteArray out = t + '(';
    for (std::size_t m = 0; m < s->members.size(); ++m) {
        const Member &member = s->members[m];
        std::optional<QByteArray> zero = zeroOf(member.type, depth + 1);
        if (!zero)
            return std::nullopt;
        if (!member.arraySize.empty()) {
            // An array member is built by an array constructor, which GLSL ES
            // 1.00 lacks, and needs its size as a number.
            if (m_es100 || !member.sizeIsLiteral)
                return std::nullopt;
            const int size =
                QByteArray(member.arraySize.data(), qsizetype(member.arraySize.size())).toInt();
            QByteArray elements;
            for (int e = 0; e < size; ++e)
                elements += (e ? "," : "") + *zero;
            zero = QByteArray(member.type.data(), qsizetype(member.type.size())) + '['
                + QByteArray::number(size) + "](" + elements + ')';
        }
        out += (m ? ", " : "") + *zero;
    }
    return out + ')';
}

// The statement that zeroes `d`, named `as` (`a = vec3(0.0);`, or a loop over
// an array's elements), or nullopt for a type PhongLab cannot build.
std::optional<QByteArray> Rewriter::zeroing(const Declared &d) const
{
    const std::optional<QByteArray> zero = zeroOf(d.type);
    if (!zero)
        return std::nullopt;
    const QByteArray name(nameOf(d).data(), qsizetype(nameOf(d).size()));
    const int begin = d.sizeBegin >= 0 ? d.sizeBegin : -1;
    if (begin < 0)
        return name + " = " + *zero + ';';
    if (d.sizeEnd <= begin)
        return std::nullopt; // `float a[];`: sized by its initializer, which it has
    const qsizetype from = m_tokens[begin].text.data() - m_code.constData();
    const qsizetype to = m_tokens[d.sizeEnd].text.data() - m_code.constData();
    const QByteArray size = m_code.mid(from, to - from).simplified();
    // A loop GLSL ES 1.00's appendix A allows: a constant bound, index++.
    return "for (int phonglab_i = 0; phonglab_i < (" + size + "); phonglab_i++) " + name
        + "[phonglab_i] = " + *zero + ';';
}

void Rewriter::insertAfter(int token, const QByteArray &text)
{
    const Token &t = m_tokens[token];
    const qsizetype offset = t.text.data() - m_code.constData() + qsizetype(t.text.size());
    m_out.insertions.push_back({offset, t.line, t.column + int(t.text.size()), text});
}

// A variable declared without a value: `= ZERO` after its name, or, for an
// array, a loop after its declaration's `;`.
void Rewriter::noteZeroed(const Declared &d)
{
    m_out.zeroed << QString::fromUtf8(nameOf(d).data(), qsizetype(nameOf(d).size()));
}

void Rewriter::zeroAtDeclaration(const Declared &d, int semicolon)
{
    if (d.sizeBegin < 0) {
        if (const std::optional<QByteArray> zero = zeroOf(d.type)) {
            insertAfter(d.name, " = " + *zero);
            noteZeroed(d);
        }
        return;
    }
    if (const std::optional<QByteArray> statement = zeroing(d)) {
        insertAfter(semicolon, ' ' + *statement);
        noteZeroed(d);
    }
}

// Statements right after `open`, the `{` of a function body.
void Rewriter::zeroAtEntry(int open, const std::vector<Declared> &variables)
{
    QByteArray statements;
    for (const Declared &d : variables) {
        if (const std::optional<QByteArray> statement = zeroing(d)) {
            statements += ' ' + *statement;
            noteZeroed(d);
        }
    }
    if (!statements.isEmpty())
        insertAfter(open, statements);
}

// A declaration at file scope from `begin` to its `;` at `end`. Outputs and
// arrays are zeroed as main() starts, other variables where declared;
// uniforms, inputs and constants are the page's or have their value.
int Rewriter::globalDeclaration(int begin, int end)
{
    bool output = false;
    int type = begin;
    for (;; ++type) {
        const std::string_view t = text(type);
        if (t == "layout") {
            type = closeOf(type + 1);
            continue;
        }
        if (oneOf(t, {"uniform", "in", "attribute", "const", "buffer", "shared", "precision"}))
            return end;
        if (t == "varying") {
            if (m_stage != ShaderStage::Vertex)
                return end;
            output = true;
            continue;
        }
        if (t == "out") {
            output = true;
            continue;
        }
        if (!isQualifier(t))
            break;
    }
    if (!isType(text(type)))
        return end;
    std::vector<Declared> unset;
    if (declarators(type, end, unset) == 0)
        return end;
    for (const Declared &d : unset) {
        if (output || d.sizeBegin >= 0)
            m_globalsAtEntry.push_back(d);
        else
            zeroAtDeclaration(d, end);
    }
    return end;
}

void Rewriter::topLevel()
{
    for (int i = 0; i < m_n;) {
        if (is(i, "struct")) {
            i = readStruct(i);
            continue;
        }
        int k = i;
        while (k < m_n && !is(k, ";") && !is(k, "{") && !is(k, "}"))
            k = is(k, "(") || is(k, "[") ? closeOf(k) + 1 : k + 1;
        if (is(k, "{")) {
            const int open = is(k - 1, ")") ? m_partner[k - 1] : -1;
            if (open > i && m_tokens[open - 1].word) {
                function(open, k);
            }
            // An interface block or a function: past its body and, for a
            // block, its declarators.
            k = closeOf(k);
            if (k < m_n && !is(k + 1, ";") && open < 0)
                while (k < m_n && !is(k, ";"))
                    ++k;
        } else if (is(k, ";")) {
            globalDeclaration(i, k);
        }
        i = k + 1;
    }
}

// A function: its `out` parameters start at zero, then its body.
void Rewriter::function(int open, int bodyOpen)
{
    const int close = closeOf(open);
    std::vector<Declared> outs;
    for (int p = open + 1; p < close;) {
        int e = p;
        while (e < close && !is(e, ","))
            e = skipBrackets(e);
        bool out = false;
        int type = p;
        for (; type < e; ++type) {
            if (is(type, "out"))
                out = true;
            else if (!isQualifier(text(type)) && !is(type, "in") && !is(type, "inout"))
                break;
        }
        if (out && type + 1 < e && m_tokens[type + 1].word) {
            Declared d{text(type), type + 1};
            if (is(type + 2, "[")) {
                d.sizeBegin = type + 3;
                d.sizeEnd = closeOf(type + 2);
            }
            outs.push_back(d);
        }
        p = e + 1;
    }
    if (text(open - 1) == "main") {
        m_mainBody = bodyOpen;
    } else {
        zeroAtEntry(bodyOpen, outs);
    }
    body(bodyOpen, closeOf(bodyOpen));
}

// The statements of a block: each declaration's variables without a value
// get one. Nested blocks and loop bodies are walked the same way.
void Rewriter::body(int open, int close)
{
    bool statementStart = true;
    for (int i = open + 1; i < close && i < m_n;) {
        if (statementStart && is(i, "struct")) {
            i = readStruct(i);
            statementStart = false;
            continue;
        }
        if (statementStart && (m_tokens[i].word)) {
            const int next = localDeclaration(i, close);
            if (next > i) {
                i = next;
                continue;
            }
        }
        const std::string_view t = text(i);
        if (t == "{") {
            body(i, closeOf(i));
            i = closeOf(i) + 1;
            statementStart = true;
            continue;
        }
        if (t == "(" || t == "[") {
            // A `for`'s own statements and a condition hold no block to walk,
            // but a loop body after them does.
            i = closeOf(i) + 1;
            statementStart = false;
            continue;
        }
        statementStart = t == ";" || t == "}";
        ++i;
    }
}

// A declaration statement starting at `begin`, or `begin` itself where the
// statement is something else. Returns the token after its `;`.
int Rewriter::localDeclaration(int begin, int close)
{
    int type = begin;
    while (type < close && isQualifier(text(type))) {
        if (is(type, "const"))
            return begin; // a constant has its value
        ++type;
    }
    if (!isType(text(type)))
        return begin;
    if (!m_tokens[std::min(type + 1, m_n - 1)].word && !is(type + 1, "["))
        return begin; // vec3(...) and the like: an expression
    int end = type + 1;
    while (end < close && !is(end, ";") && !is(end, "{") && !is(end, "}"))
        end = skipBrackets(end);
    if (!is(end, ";"))
        return begin;
    std::vector<Declared> unset;
    if (declarators(type, end, unset) == 0)
        return begin;
    for (const Declared &d : unset)
        zeroAtDeclaration(d, end);
    return end + 1;
}

BrowserRewrite Rewriter::run()
{
    m_out.code = m_code;
    if (std::size_t(m_n) > kMaxTokens)
        return m_out;
    m_partner = bracketPartners(m_tokens);
    topLevel();
    if (m_mainBody >= 0) {
        std::vector<Declared> atEntry;
        const auto mentions = [&](std::string_view word) {
            return std::any_of(m_tokens.begin(), m_tokens.end(),
                               [&](const Token &t) { return t.text == word; });
        };
        // The built-in outputs, each where the shader uses it (a shader
        // that writes gl_FragData may not name gl_FragColor); gl_Position
        // always. Of gl_FragData only the first: without EXT_draw_buffers
        // WebGL has one.
        if (m_stage == ShaderStage::Vertex) {
            atEntry.push_back({"vec4", -1, -1, -1, "gl_Position"});
            if (mentions("gl_PointSize"))
                atEntry.push_back({"float", -1, -1, -1, "gl_PointSize"});
        } else {
            for (std::string_view builtIn : {"gl_FragColor", "gl_FragData"})
                if (mentions(builtIn))
                    atEntry.push_back({"vec4", -1, -1, -1,
                                       builtIn == "gl_FragData" ? "gl_FragData[0]" : builtIn});
            if (mentions("gl_FragDepth"))
                atEntry.push_back({"float", -1, -1, -1, "gl_FragDepth"});
        }
        atEntry.insert(atEntry.end(), m_globalsAtEntry.begin(), m_globalsAtEntry.end());
        zeroAtEntry(m_mainBody, atEntry);
    }
    std::stable_sort(
        m_out.insertions.begin(), m_out.insertions.end(),
        [](const SourceInsertion &a, const SourceInsertion &b) { return a.offset < b.offset; });
    QByteArray code;
    code.reserve(m_code.size() + 64 * qsizetype(m_out.insertions.size()));
    qsizetype from = 0;
    for (const SourceInsertion &at : m_out.insertions) {
        code += m_code.mid(from, at.offset - from);
        code += at.text;
        from = at.offset;
    }
    code += m_code.mid(from);
    m_out.code = code;
    return m_out;
}

} // namespace

BrowserRewrite applyBrowserRules(const QByteArray &code, ShaderStage stage)
{
    return Rewriter(code, stage).run();
}

} // namespace phonglab
