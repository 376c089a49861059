#include "core/program/BindingsByUse.h"

#include "core/program/UseTokens.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <string_view>

namespace phonglab {

namespace {

struct BindingsByUseWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::BindingsByUse)
};

using namespace glsl;
using namespace usetokens;
using M = BindingMeaning;

// The pieces of projection · view · model a matrix meaning covers, as the
// first and last index of {0: projection, 1: view, 2: model}.
struct Span {
    int first = 0;
    int last = 0;
};
std::optional<Span> spanOf(M meaning)
{
    switch (meaning) {
    case M::Projection: return Span{0, 0};
    case M::View: return Span{1, 1};
    case M::Model: return Span{2, 2};
    case M::ModelView: return Span{1, 2};
    case M::ViewProjection: return Span{0, 1};
    case M::ModelViewProjection: return Span{0, 2};
    default: return std::nullopt;
    }
}
M meaningOfSpan(Span s)
{
    static const M table[3][3] = {{M::Projection, M::ViewProjection, M::ModelViewProjection},
                                  {M::Projection, M::View, M::ModelView},
                                  {M::Projection, M::View, M::Model}};
    return table[s.first][s.last];
}

// Spans for `count` matrices no name decided, covering pieces [first, last]
// in order; empty where they cannot (fewer pieces than matrices).
std::vector<Span> fill(int count, int first, int last)
{
    const int pieces = last - first + 1;
    if (count <= 0 || count > pieces)
        return {};
    if (count == 1)
        return {{first, last}};
    if (count == pieces) {
        std::vector<Span> out;
        for (int p = first; p <= last; ++p)
            out.push_back({p, p});
        return out;
    }
    // Two for three: projection, then model-view (Angel's, the exercise's).
    return {{first, first}, {first + 1, last}};
}

class UseReader : UseTokens
{
public:
    UseReader(const QByteArray &code, ShaderStage stage, ProgramBindings &bindings)
        : UseTokens(code, bindings)
        , m_stage(stage)
        , m_bindings(bindings)
    {
    }

    int run()
    {
        if (std::size_t(m_n) > kMaxUseTokens)
            return 0;
        for (int i = 0; i < m_n; ++i) {
            if (is(i, "pow") && is(i + 1, "("))
                exponent(i);
            else if (is(i, "for") && is(i + 1, "("))
                loopBound(i);
            else if (is(i, "gl_Position") && is(i + 1, "=") && m_stage == ShaderStage::Vertex)
                positionChain(i + 2);
            else if (word(i))
                subtractedFromPosition(i);
            if (is(i, "-") && word(i - 1) && isSurfaceWord(i + 1))
                movedThenSubtracted(i - 1);
        }
        return m_bound;
    }

private:
    bool unbound(int v) const
    {
        const VariableBinding &b = m_bindings.variables[std::size_t(v)];
        return !b.meaning && !b.isExplicit && !b.variable.isInput;
    }
    void bind(const std::vector<int> &variables, M meaning, int at, const QString &reason);

    void exponent(int pow);
    void loopBound(int forWord);
    void positionChain(int begin);
    void chainFactors(int begin, int end, int depth, std::vector<int> &matrices) const;
    void subtractedFromPosition(int i);
    bool isSurfaceWord(int i) const;
    void movedThenSubtracted(int localToken);
    bool usedAsLightDirection(int statementBegin) const;

    ShaderStage m_stage;
    ProgramBindings &m_bindings;
    int m_bound = 0;
};

void UseReader::bind(const std::vector<int> &variables, M meaning, int at, const QString &reason)
{
    for (int v : variables) {
        VariableBinding &b = m_bindings.variables[std::size_t(v)];
        if (!unbound(v) || !bindingFits(meaning, b.variable))
            continue;
        b.meaning = meaning;
        b.byUse = UseEvidence{m_stage, line(at), reason};
        ++m_bound;
    }
}

// pow(R·V, n): n is the shininess.
void UseReader::exponent(int pow)
{
    const int close = closeOf(pow + 1);
    const int comma = until(pow + 2, ",");
    if (!is(comma, ",") || comma >= close)
        return;
    bind(referenceIn(comma + 1, close), M::Shininess, pow,
         BindingsByUseWords::tr("the exponent of pow"));
}

// for (int i = 0; i < n; ++i) { ... u[i] ... }, or WebGL 1's
// for (int i = 0; i < MAX; ++i) { if (i >= n) break; ... }: n is the light count.
void UseReader::loopBound(int forWord)
{
    const int open = forWord + 1;
    const int close = closeOf(open);
    const int initEnd = until(open + 1, ";");
    if (!is(initEnd, ";") || !is(initEnd - 4, "int") || !is(initEnd - 2, "="))
        return;
    const std::string_view index = text(initEnd - 3);
    const int body = close + 1;
    const int bodyEnd = is(body, "{") ? closeOf(body) : until(body, ";");
    // `u[i]`, or `u[int(clamp(float(i), ...))]` as the browser's rules write it.
    bool indexesArrays = false;
    for (int k = body; k < bodyEnd && !indexesArrays; ++k)
        if (is(k, "["))
            for (int a = k + 1; a < closeOf(k) && !indexesArrays; ++a)
                indexesArrays = text(a) == index;
    if (!indexesArrays)
        return;
    const QString reason = BindingsByUseWords::tr("bounds the loop over the lights");
    const int condition = initEnd + 1;
    const int conditionEnd = until(condition, ";");
    if (text(condition) == index && oneOf(text(condition + 1), {"<", "<="}))
        bind(referenceIn(condition + 2, conditionEnd), M::LightCount, condition, reason);
    for (int k = body; k < bodyEnd; ++k) {
        if (!is(k, "if") || !is(k + 1, "(") || text(k + 2) != index
            || !oneOf(text(k + 3), {">=", "==", ">"}))
            continue;
        const int testEnd = closeOf(k + 1);
        if (oneOf(text(testEnd + 1), {"break", "{"}) || is(testEnd + 2, "break"))
            bind(referenceIn(k + 4, testEnd), M::LightCount, k, reason);
    }
}

// The matrices a product [begin, end) multiplies the position by, outermost
// first: factors joined by `*`, parentheses and locals followed.
void UseReader::chainFactors(int begin, int end, int depth, std::vector<int> &matrices) const
{
    for (int f = begin; f < end;) {
        int e = f;
        while (e < end && !is(e, "*"))
            e = next(e);
        if (is(f, "(") && closeOf(f) == e - 1) {
            chainFactors(f + 1, e - 1, depth, matrices);
        } else if (const std::vector<int> vars = referenceIn(f, e); vars.size() == 1) {
            const GlslType type = m_bindings.variables[std::size_t(vars[0])].variable.type;
            if (type == GlslType::Mat4)
                matrices.push_back(vars[0]);
        } else if (e == f + 1 && word(f) && depth < kMaxFollow) {
            if (const int init = initializerOf(text(f), f); init >= 0)
                chainFactors(init, until(init, ";"), depth + 1, matrices);
        }
        f = e + 1;
    }
}

// gl_Position = P * V * M * position: each unknown matrix's place.
void UseReader::positionChain(int begin)
{
    std::vector<int> chain;
    chainFactors(begin, until(begin, ";"), 0, chain);
    std::vector<std::pair<int, Span>> spans; // chain index, span
    int piece = 0;
    std::vector<int> pending; // chain indices no name decided, since the last known
    const auto settle = [&](int last) {
        const std::vector<Span> filled = fill(int(pending.size()), piece, last);
        if (filled.size() != pending.size())
            return false;
        for (std::size_t k = 0; k < pending.size(); ++k)
            spans.push_back({pending[k], filled[k]});
        pending.clear();
        return true;
    };
    for (std::size_t c = 0; c < chain.size(); ++c) {
        const VariableBinding &b = m_bindings.variables[std::size_t(chain[c])];
        if (unbound(chain[c])) {
            pending.push_back(int(c));
            continue;
        }
        const std::optional<Span> known = b.meaning ? spanOf(*b.meaning) : std::nullopt;
        if (!known || known->first < piece || !settle(known->first - 1))
            return;
        piece = known->last + 1;
    }
    if (!pending.empty() && !settle(2))
        return;
    const QString reason =
        BindingsByUseWords::tr("its place in the gl_Position chain (projection · view · model)");
    for (const auto &[c, span] : spans)
        bind({chain[std::size_t(c)]}, meaningOfSpan(span), begin, reason);
}

// Whether the token at `i` is a word for the surface's position: no
// uniform, no call, no type.
bool UseReader::isSurfaceWord(int i) const
{
    int end = i;
    return word(i) && !isKeyword(text(i)) && !isTypeName(text(i)) && !is(i + 1, "(")
        && variablesAt(i, &end).empty();
}

// light - P (or P - light): a light's position (or, where the shader names
// a light already, the eye's).
void UseReader::subtractedFromPosition(int i)
{
    if (is(i - 1, "."))
        return;
    int end = i;
    std::vector<int> vars = variablesAt(i, &end);
    std::erase_if(vars, [&](int v) {
        const GlslType t = m_bindings.variables[std::size_t(v)].variable.type;
        return !unbound(v) || (t != GlslType::Vec3 && t != GlslType::Vec4);
    });
    if (vars.empty())
        return;
    int surface = -1;
    if (is(end, "-") && isSurfaceWord(end + 1))
        surface = end + 1;
    else if (is(i - 1, "-") && isSurfaceWord(i - 2) && !is(i - 3, "."))
        surface = i - 2;
    if (surface < 0)
        return;
    int statement = i;
    while (statement > 0 && !oneOf(text(statement - 1), {";", "{", "}"}))
        --statement;
    const bool perLight = m_bindings.variables[std::size_t(vars[0])].variable.isArray
        || m_bindings.variables[std::size_t(vars[0])].variable.name.contains(QLatin1Char('['));
    const bool lightNamed = !m_bindings.bound(M::LightPosition).empty()
        || !m_bindings.bound(M::LightPositionCamera).empty();
    if (perLight || usedAsLightDirection(statement) || !lightNamed) {
        bind(vars, M::LightPosition, i,
             BindingsByUseWords::tr("subtracted from the surface position %1, as a light's "
                                    "position (world coordinates)")
                 .arg(toQString(text(surface))));
    } else if (m_bindings.bound(M::Eye).empty()) {
        bind(vars, M::Eye, i,
             BindingsByUseWords::tr("subtracted from the surface position %1, as the eye's")
                 .arg(toQString(text(surface))));
    }
}

// lightCam - P, where lightCam = (V * vec4(light, 1.0)).xyz: the vector a
// local was moved from is a light's position, world coordinates.
void UseReader::movedThenSubtracted(int localToken)
{
    if (is(localToken - 1, ".") || !isSurfaceWord(localToken))
        return;
    const int init = initializerOf(text(localToken), localToken);
    int statement = localToken;
    while (statement > 0 && !oneOf(text(statement - 1), {";", "{", "}"}))
        --statement;
    if (init < 0 || !usedAsLightDirection(statement))
        return; // the eye's position is moved and subtracted too
    const int end = until(init, ";");
    std::vector<int> moved;  // the vectors
    std::vector<int> movers; // the matrices that moved them
    for (int k = init; k < end; ++k) {
        int after = k;
        for (int v : variablesAt(k, &after)) {
            const GlslType t = m_bindings.variables[std::size_t(v)].variable.type;
            if (!unbound(v))
                continue;
            if (t == GlslType::Vec3 || t == GlslType::Vec4)
                moved.push_back(v);
            else if (t == GlslType::Mat4)
                movers.push_back(v);
        }
    }
    const QString local = toQString(text(localToken));
    const QString surface = toQString(text(localToken + 2));
    bind(moved, M::LightPosition, init,
         BindingsByUseWords::tr("moved into %1 and subtracted from the surface position %2, "
                                "as a light's position (world coordinates)")
             .arg(local, surface));
    // The exercise's step 3: the view matrix takes the light from world
    // into camera coordinates.
    if (!moved.empty() && movers.size() == 1)
        bind(movers, M::View, init,
             BindingsByUseWords::tr("moves the light's position into camera coordinates (%1)")
                 .arg(local));
}

// Whether the local the statement at `statementBegin` sets is a light
// direction: reflected, or dotted with anything but a reflection (the view
// vector is dotted with R = reflect(...)).
bool UseReader::usedAsLightDirection(int statementBegin) const
{
    int eq = statementBegin;
    while (eq < m_n && !is(eq, "=") && !is(eq, ";"))
        ++eq;
    if (!is(eq, "=") || !word(eq - 1))
        return false;
    // The local, and the locals made from it (`L = toLight / d`).
    std::vector<std::string_view> locals{text(eq - 1)};
    for (int k = eq + 1; k < m_n && locals.size() < std::size_t(kMaxFollow); ++k) {
        if (!is(k, "=") || !word(k - 1)
            || std::find(locals.begin(), locals.end(), text(k - 1)) != locals.end())
            continue;
        const int end = until(k + 1, ";");
        for (int a = k + 1; a < end; ++a)
            if (std::find(locals.begin(), locals.end(), text(a)) != locals.end()) {
                locals.push_back(text(k - 1));
                break;
            }
    }
    const auto isReflection = [&](int a) {
        const int init = word(a) ? initializerOf(text(a), m_n) : -1;
        return init >= 0 && is(init, "reflect");
    };
    const auto mine = [&](int k) {
        return std::find(locals.begin(), locals.end(), text(k)) != locals.end() && !is(k - 1, ".");
    };
    for (int k = eq + 1; k < m_n; ++k) {
        if (!mine(k))
            continue;
        const int around = enclosingCall(k);
        if (is(around, "reflect"))
            return true;
        if (is(around, "dot")) {
            // The view vector is dotted with the reflection.
            const int close = closeOf(around + 1);
            bool reflection = false;
            bool other = false;
            for (int a = around + 2; a < close; ++a) {
                reflection = reflection || is(a, "reflect") || isReflection(a);
                other = other || (word(a) && !mine(a));
            }
            if (other && !reflection)
                return true;
        }
    }
    return false;
}

} // namespace

int bindByUse(ProgramBindings &bindings, const QByteArray &vertex, const QByteArray &fragment)
{
    // The vertex stage first: its gl_Position chain places the matrices
    // before the fragment stage's subtractions are read.
    int bound = UseReader(vertex, ShaderStage::Vertex, bindings).run();
    bound += UseReader(fragment, ShaderStage::Fragment, bindings).run();
    // The terms' factors last: a vector the rules above placed (a light's
    // position) is no factor of a term.
    return bound + bindTermFactors(bindings, vertex, fragment);
}

} // namespace phonglab
