// The zero of each type, and where it goes (BrowserRulesRewriter.h): `= 0.0`
// after a name, a loop over an array's elements, a constructor of a
// struct's members.
#include "core/program/BrowserRulesRewriter.h"

namespace phonglab::browserrules {

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
    if (d.sizeEnd <= begin || d.sizeEnd >= m_n)
        return std::nullopt; // `float a[];`: sized by its initializer, which it has
    const qsizetype from = m_tokens[begin].text.data() - m_code.constData();
    const qsizetype to = m_tokens[d.sizeEnd].text.data() - m_code.constData();
    const QByteArray size = m_code.mid(from, to - from).simplified();
    // A loop GLSL ES 1.00's appendix A allows: a constant bound, index++.
    return "for (int phonglab_i = 0; phonglab_i < (" + size + "); phonglab_i++) " + name
        + "[phonglab_i] = " + *zero + ';';
}

void Rewriter::insertBefore(int token, const QByteArray &text)
{
    const Token &t = m_tokens[std::size_t(token)];
    m_out.insertions.push_back({t.text.data() - m_code.constData(), t.line, t.column, text});
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

} // namespace phonglab::browserrules
