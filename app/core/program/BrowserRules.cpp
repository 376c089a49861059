#include "core/program/BrowserRules.h"

#include "core/program/BrowserRulesRewriter.h"

#include <algorithm>
#include <map>

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

namespace browserrules {

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

// Whether the `[` at `open` sizes an array where it is declared
// (`vec3 a[3]`, `float b[2], c[N];`, a parameter) rather than indexes one.
bool Rewriter::isDeclarationBracket(int open) const
{
    const int before = open - 2;
    if (isType(text(before)) || isQualifier(text(before)))
        return true;
    if (!is(before, ",") || !oneOf(text(closeOf(open) + 1), {";", ",", "="}))
        return false;
    int start = before;
    while (start > 0 && !oneOf(text(start - 1), {";", "{", "}"}))
        --start;
    while (isQualifier(text(start))
           || oneOf(text(start), {"uniform", "in", "out", "varying", "attribute"}))
        ++start;
    return isType(text(start));
}

// ANGLE clamps every index that is no constant into the array
// (clampIndirectArrayBounds): `a[i]` reads `a[clamp(i, 0, N - 1)]`, so an
// index past the end reads the last element in the browser. The same for
// every array the shader declares with a size; members of structs and
// vectors are left as they are.
void Rewriter::clampIndices()
{
    std::map<std::string_view, QByteArray> sizes; // empty: sized twice, differently
    std::vector<bool> declaring(std::size_t(m_n), false);
    for (int i = 1; i + 1 < m_n; ++i) {
        if (!is(i, "[") || !m_tokens[std::size_t(i - 1)].word || !isDeclarationBracket(i))
            continue;
        declaring[std::size_t(i)] = true;
        const int close = closeOf(i);
        if (close >= m_n || close == i + 1)
            continue;
        const qsizetype from = m_tokens[std::size_t(i + 1)].text.data() - m_code.constData();
        const qsizetype to = m_tokens[std::size_t(close)].text.data() - m_code.constData();
        const QByteArray size = m_code.mid(from, to - from).simplified();
        const auto [it, added] = sizes.try_emplace(text(i - 1), size);
        if (!added && it->second != size)
            it->second.clear();
    }
    for (int i = 1; i + 2 < m_n; ++i) {
        if (!is(i, "[") || declaring[std::size_t(i)] || is(i - 2, "."))
            continue;
        const auto it = sizes.find(text(i - 1));
        const int close = closeOf(i);
        if (it == sizes.end() || it->second.isEmpty() || close >= m_n
            || (close == i + 2 && isDigit(text(i + 1)[0])))
            continue; // a constant index ANGLE checks when it compiles
        insertAfter(i, "int(clamp(float(");
        insertBefore(close, "), 0.0, float(" + it->second + ") - 1.0))");
    }
}

BrowserRewrite Rewriter::run()
{
    m_out.code = m_code;
    if (std::size_t(m_n) > kMaxTokens)
        return m_out;
    m_partner = bracketPartners(m_tokens);
    topLevel();
    clampIndices();
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

} // namespace browserrules

BrowserRewrite applyBrowserRules(const QByteArray &code, ShaderStage stage)
{
    return browserrules::Rewriter(code, stage).run();
}

} // namespace phonglab
