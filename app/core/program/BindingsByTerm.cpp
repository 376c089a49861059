// Binding by use, the terms' factors: colours and gains that scale the
// ambient, diffuse or specular term (BindingsByUse.h). Each assignment's
// value is read as a sum of products; a product holding pow(...) is the
// specular term, one holding dot(...) the diffuse term, and one of uniforms
// alone, reaching an output, the ambient term. Locals carry their products
// into the expressions that use them, so `vec3 diffuse = kd * Id * NdotL;
// color = ambient + diffuse;` is read as the student means it.
#include "core/program/UseTokens.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <map>

namespace phonglab::usetokens {

namespace {

struct TermWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::BindingsByUse)
};

using namespace glsl;
using M = BindingMeaning;

enum class Term {
    None, // uniforms alone: ambient where it reaches an output
    Diffuse,
    Specular,
    Mixed, // both: nothing can be said
};

struct Factor {
    int variable = -1;
    int line = 0; // where it was read
    ShaderStage stage = ShaderStage::Fragment;
    int element = -1; // `m[1]`: the column or element taken; -1 for the whole
};

struct Product {
    Term term = Term::None;
    std::vector<Factor> factors;
};
using Sum = std::vector<Product>;

constexpr std::size_t kMaxProducts = 64;

Term joined(Term a, Term b)
{
    if (a == Term::None || a == b)
        return b;
    return b == Term::None ? a : Term::Mixed;
}

// Every product of `a` times every product of `b`.
Sum times(const Sum &a, const Sum &b)
{
    Sum out;
    for (const Product &x : a)
        for (const Product &y : b) {
            if (out.size() >= kMaxProducts)
                return out;
            Product p{joined(x.term, y.term), x.factors};
            p.factors.insert(p.factors.end(), y.factors.begin(), y.factors.end());
            out.push_back(std::move(p));
        }
    return out;
}

class TermReader : UseTokens
{
public:
    TermReader(const QByteArray &code, ShaderStage stage, const ProgramBindings &bindings)
        : UseTokens(code, bindings)
        , m_stage(stage)
    {
    }

    // The products that reach the stage's outputs.
    Sum run();

private:
    Sum sum(int begin, int end, int depth) const;
    Sum operand(int begin, int end, int depth) const;
    Term callTerm(int name) const;
    bool isOutput(std::string_view name) const;
    void assignment(int statement);

    ShaderStage m_stage;
    std::map<std::string_view, Sum> m_values; // locals, outputs and functions
    std::vector<std::string_view> m_outputs;
    std::string_view m_function; // the function whose body is being read
};

// The equation's own calls mark a product's term; any other call hides
// what it holds.
Term TermReader::callTerm(int name) const
{
    const int close = closeOf(name + 1);
    bool dotted = false;
    for (int k = name; k < close; ++k) {
        if (is(k, "pow") && is(k + 1, "("))
            return Term::Specular;
        dotted = dotted || (is(k, "dot") && is(k + 1, "("));
    }
    return dotted ? Term::Diffuse : Term::None;
}

Sum TermReader::operand(int begin, int end, int depth) const
{
    if (depth > 2 * kMaxFollow || begin >= end)
        return {Product{}};
    if (is(begin, "(") && closeOf(begin) == end - 1)
        return sum(begin + 1, end - 1, depth + 1);
    if (word(begin) && is(begin + 1, "(") && closeOf(begin + 1) == end - 1) {
        // vec3(a * b) and vec4(c, 1.0): the value is the first argument's.
        if (isTypeName(text(begin)))
            return sum(begin + 2, until(begin + 2, ","), depth + 1);
        if (const auto it = m_values.find(text(begin)); it != m_values.end())
            return it->second; // a function of the shader's: what it returns
        return {Product{callTerm(begin), {}}};
    }
    int after = begin;
    const std::vector<int> vars = variablesAt(begin, &after);
    if (!vars.empty() && after == end) {
        const bool element =
            is(begin + 1, "[") && closeOf(begin + 1) == begin + 3 && isDigit(text(begin + 2)[0]);
        Product p;
        for (int v : vars)
            p.factors.push_back({v, line(begin), m_stage, element ? text(begin + 2)[0] - '0' : -1});
        return {p};
    }
    if (end == begin + 1 || (is(begin + 1, ".") && end == begin + 3)) // a local, or its swizzle
        if (const auto it = m_values.find(text(begin)); it != m_values.end())
            return it->second;
    return {Product{}};
}

// [begin, end) as a sum of products: split at the top level's + and -,
// each piece at its *. Of `c ? a : b` both branches count.
Sum TermReader::sum(int begin, int end, int depth) const
{
    Sum out;
    int question = begin;
    while (question < end && !is(question, "?"))
        question = next(question);
    if (question < end && depth <= 2 * kMaxFollow) {
        int colon = question + 1;
        while (colon < end && !is(colon, ":"))
            colon = next(colon);
        out = sum(question + 1, colon, depth + 1);
        const Sum otherwise = sum(colon + 1, end, depth + 1);
        out.insert(out.end(), otherwise.begin(), otherwise.end());
        // `N·L > 0.0 ? pow(...) : 0.0`: the constant branch is no term.
        const bool termed = std::any_of(out.begin(), out.end(),
                                        [](const Product &p) { return p.term != Term::None; });
        if (termed)
            std::erase_if(
                out, [](const Product &p) { return p.term == Term::None && p.factors.empty(); });
        return out;
    }
    for (int piece = begin; piece < end;) {
        int e = piece;
        while (e < end && !oneOf(text(e), {"+", "-"}))
            e = next(e);
        Sum product{Product{}};
        for (int f = piece; f < e;) {
            int g = f;
            while (g < e && !oneOf(text(g), {"*", "/"}))
                g = next(g);
            if (!is(f - 1, "/")) // a divisor scales no term the way a factor does
                product = times(product, operand(f, g, depth));
            f = g + 1;
        }
        out.insert(out.end(), product.begin(), product.end());
        if (out.size() > kMaxProducts)
            out.resize(kMaxProducts);
        piece = e + 1;
    }
    return out;
}

bool TermReader::isOutput(std::string_view name) const
{
    return name == "gl_FragColor" || name == "gl_FragData"
        || std::find(m_outputs.begin(), m_outputs.end(), name) != m_outputs.end();
}

// `[TYPE] NAME (= | += | *=) EXPR;` and `return EXPR;` at `statement`.
void TermReader::assignment(int statement)
{
    if (is(statement, "return")) {
        if (!m_function.empty())
            m_values[m_function] = sum(statement + 1, until(statement + 1, ";"), 0);
        return;
    }
    int name = statement;
    while (word(name) && word(name + 1))
        ++name; // qualifiers and the type
    int op = name + 1;
    if (is(op, "[")) // gl_FragData[0]
        op = closeOf(op) + 1;
    if (is(op, ".") && word(op + 1)) // a swizzle written: the variable's value grows
        op += 2;
    if (!word(name) || !oneOf(text(op), {"=", "+=", "*="}))
        return;
    const int end = until(op + 1, ";");
    Sum value = sum(op + 1, end, 0);
    Sum &held = m_values[text(name)];
    if (is(op, "=") && !is(name + 1, "."))
        held = std::move(value);
    else if (is(op, "*="))
        held = times(held.empty() ? Sum{Product{}} : held, value);
    else
        held.insert(held.end(), value.begin(), value.end());
    if (held.size() > kMaxProducts)
        held.resize(kMaxProducts);
}

Sum TermReader::run()
{
    if (std::size_t(m_n) > kMaxUseTokens)
        return {};
    int depth = 0;
    for (int i = 0; i < m_n; ++i) {
        const bool statementStart = i == 0 || oneOf(text(i - 1), {";", "{", "}"});
        if (depth == 0 && (is(i, "out") || (is(i, "varying") && m_stage == ShaderStage::Vertex))) {
            int name = i + 1;
            while (word(name + 1))
                ++name;
            m_outputs.push_back(text(name));
        }
        if (depth == 0 && is(i, "(") && word(i - 1) && is(closeOf(i) + 1, "{"))
            m_function = text(i - 1);
        if (is(i, "{"))
            ++depth;
        else if (is(i, "}"))
            depth = std::max(0, depth - 1);
        else if (statementStart && depth > 0 && word(i))
            assignment(i);
    }
    Sum out;
    for (const auto &[name, value] : m_values)
        if (isOutput(name))
            out.insert(out.end(), value.begin(), value.end());
    return out;
}

// Which of a term's parts a meaning holds.
struct Parts {
    bool light = false;    // Ia, Id, Is
    bool material = false; // ka, kd, ks
};

Parts partsOf(M meaning, Term term)
{
    const bool diffuse = term == Term::Diffuse;
    const bool specular = term == Term::Specular;
    const bool ambient = term == Term::None;
    switch (meaning) {
    case M::AmbientProduct: return {ambient, ambient};
    case M::DiffuseProduct: return {diffuse, diffuse};
    case M::SpecularProduct: return {specular, specular};
    case M::Ambient: return {ambient, false};
    case M::LightDiffuse: return {diffuse, false};
    case M::LightSpecular: return {specular, false};
    case M::LightColor: return {diffuse || specular, false};
    case M::Ka: return {false, ambient};
    case M::Kd: return {false, diffuse};
    case M::Ks: return {false, specular};
    case M::MaterialColor: return {false, ambient || diffuse};
    case M::LightTerms: return {true, false};
    case M::MaterialTerms: return {false, true};
    default: return {};
    }
}

struct TermMeanings {
    M product;
    M light;
    M material;
    const char *reason;
};
TermMeanings meaningsOf(Term term)
{
    switch (term) {
    case Term::Diffuse:
        return {M::DiffuseProduct, M::LightDiffuse, M::Kd,
                QT_TRANSLATE_NOOP("phonglab::BindingsByUse", "scales the diffuse term")};
    case Term::Specular:
        return {M::SpecularProduct, M::LightSpecular, M::Ks,
                QT_TRANSLATE_NOOP("phonglab::BindingsByUse", "scales the specular term")};
    default:
        return {M::AmbientProduct, M::Ambient, M::Ka,
                QT_TRANSLATE_NOOP("phonglab::BindingsByUse", "scales the ambient term")};
    }
}

// What one term's factors mean, given the parts the names already hold: the
// one vector no name decided takes what is missing (the product, I or k), the
// gains no name decided are 1. Where only gains are left and a named vector
// holds a part of its own term alone, it takes the whole product instead:
// any split whose factors multiply to I·k is right.
class TermBinder
{
public:
    explicit TermBinder(ProgramBindings &bindings)
        : m_bindings(bindings)
    {
    }
    int bind(Term term, const std::vector<Factor> &factors, const std::vector<int> &shared);

private:
    VariableBinding &at(int v) { return m_bindings.variables[std::size_t(v)]; }
    bool unbound(int v) { return !at(v).meaning && !at(v).isExplicit && !at(v).variable.isInput; }
    void give(const Factor &f, M meaning, const QString &reason);

    ProgramBindings &m_bindings;
    int m_bound = 0;
};

void TermBinder::give(const Factor &f, M meaning, const QString &reason)
{
    VariableBinding &b = at(f.variable);
    if (!bindingFits(meaning, b.variable))
        return;
    b.meaning = meaning;
    b.byUse = UseEvidence{f.stage, f.line, reason};
    ++m_bound;
}

int TermBinder::bind(Term term, const std::vector<Factor> &factors, const std::vector<int> &shared)
{
    const TermMeanings meanings = meaningsOf(term);
    const QString reason = TermWords::tr(meanings.reason);
    const auto isShared = [&](int v) {
        return std::find(shared.begin(), shared.end(), v) != shared.end();
    };
    Parts covered;
    std::vector<Factor> vectors;
    std::vector<Factor> gains;
    const Factor *named = nullptr; // a vector a name gave one part of this term alone
    for (const Factor &f : factors) {
        const VariableBinding &b = at(f.variable);
        const GlslType type = b.variable.type;
        const bool vector = type == GlslType::Vec3 || type == GlslType::Vec4;
        if (b.meaning) {
            const Parts p = partsOf(*b.meaning, term);
            covered.light = covered.light || p.light;
            covered.material = covered.material || p.material;
            if (vector && p.light != p.material && !b.isExplicit && !isShared(f.variable))
                named = &f;
        } else if (unbound(f.variable) && vector && !isShared(f.variable)) {
            vectors.push_back(f);
        } else if (unbound(f.variable) && type == GlslType::Float) {
            gains.push_back(f);
        }
    }
    const int before = m_bound;
    if (!(covered.light && covered.material)) {
        const M missing = !covered.light && !covered.material ? meanings.product
            : covered.light                                   ? meanings.material
                                                              : meanings.light;
        if (!vectors.empty()) {
            give(vectors.front(), missing, reason);
            vectors.erase(vectors.begin());
        } else if (!gains.empty() && named) {
            give(*named, meanings.product,
                 TermWords::tr("holds the whole %1 beside the gain %2")
                     .arg(bindingMeaningDescription(meanings.product),
                          at(gains.front().variable).variable.name));
        } else if (factors.size() == 1 && named) {
            // The term's one factor can only be all of it, whatever part its
            // name suggests (webglfundamentals' u_specularColor).
            give(*named, meanings.product,
                 TermWords::tr("the term's only factor: %1")
                     .arg(bindingMeaningDescription(meanings.product)));
        } else {
            return 0;
        }
    } else if (vectors.empty() && gains.empty()) {
        return 0;
    }
    // What is left, vectors and gains, is 1: the term already has its value.
    for (const std::vector<Factor> *rest : {&vectors, &gains})
        for (const Factor &g : *rest)
            if (unbound(g.variable))
                give(g, M::Gain, reason);
    return m_bound - before;
}

// The term a column or element stands for in the equation's order.
int termColumn(Term term)
{
    return term == Term::None ? 0 : term == Term::Diffuse ? 1 : 2;
}

// A mat3 or vec3[3] whose column k scales term k (ambient, diffuse,
// specular) in two terms or more holds their light parts where the other
// factors are the material's, or their material parts where they are the
// light's: `light-terms`, `material-terms`.
int bindTermColumns(ProgramBindings &bindings, const Sum &reaching)
{
    std::map<int, std::vector<const Product *>> uses; // variable -> products with a column of it
    for (const Product &p : reaching)
        for (const Factor &f : p.factors)
            if (f.element >= 0 && p.term != Term::Mixed)
                uses[f.variable].push_back(&p);
    int bound = 0;
    for (const auto &[variable, products] : uses) {
        VariableBinding &b = bindings.variables[std::size_t(variable)];
        if (b.meaning || b.isExplicit || !bindingFits(M::LightTerms, b.variable))
            continue;
        std::vector<Term> terms;
        bool inOrder = true;
        Parts others;
        const Factor *first = nullptr;
        for (const Product *p : products) {
            for (const Factor &f : p->factors) {
                const std::optional<M> meaning =
                    bindings.variables[std::size_t(f.variable)].meaning;
                if (f.variable != variable) {
                    const Parts parts = meaning ? partsOf(*meaning, p->term) : Parts{};
                    others.light = others.light || parts.light;
                    others.material = others.material || parts.material;
                    continue;
                }
                first = first ? first : &f;
                inOrder = inOrder && f.element == termColumn(p->term);
                if (std::find(terms.begin(), terms.end(), p->term) == terms.end())
                    terms.push_back(p->term);
            }
        }
        if (!inOrder || terms.size() < 2 || others.light == others.material || !first)
            continue;
        b.meaning = others.material ? M::LightTerms : M::MaterialTerms;
        b.byUse = UseEvidence{first->stage, first->line,
                              TermWords::tr("its columns scale the ambient, diffuse and specular "
                                            "terms in that order")};
        ++bound;
    }
    return bound;
}

} // namespace

int bindTermFactors(ProgramBindings &bindings, const QByteArray &vertex, const QByteArray &fragment)
{
    Sum reaching = TermReader(vertex, ShaderStage::Vertex, bindings).run();
    const Sum fromFragment = TermReader(fragment, ShaderStage::Fragment, bindings).run();
    reaching.insert(reaching.end(), fromFragment.begin(), fromFragment.end());
    const bool lit = std::any_of(reaching.begin(), reaching.end(), [](const Product &p) {
        return p.term == Term::Diffuse || p.term == Term::Specular;
    });
    if (!lit)
        return 0;
    // Where one unlit product holds the ambient term by name (Angel's
    // `ambientProduct`), another unlit one added beside it is no part of it:
    // `+= uZork` is the student's own, not the ambient term's gain.
    const auto holdsAmbient = [&](const Product &p) {
        return std::any_of(p.factors.begin(), p.factors.end(), [&](const Factor &f) {
            const auto &meaning = bindings.variables[std::size_t(f.variable)].meaning;
            if (!meaning)
                return false;
            const Parts parts = partsOf(*meaning, Term::None);
            return parts.light || parts.material;
        });
    };
    const bool ambientNamed = std::any_of(reaching.begin(), reaching.end(), [&](const Product &p) {
        return p.term == Term::None && holdsAmbient(p);
    });
    // Each term's factors, each variable once; a variable in two terms is shared.
    std::map<Term, std::vector<Factor>> terms;
    std::map<int, std::vector<Term>> termsOf;
    for (const Product &p : reaching) {
        if (p.term == Term::Mixed || (p.term == Term::None && ambientNamed && !holdsAmbient(p)))
            continue;
        for (const Factor &f : p.factors) {
            std::vector<Factor> &list = terms[p.term];
            if (std::none_of(list.begin(), list.end(),
                             [&](const Factor &g) { return g.variable == f.variable; }))
                list.push_back(f);
            std::vector<Term> &in = termsOf[f.variable];
            if (std::find(in.begin(), in.end(), p.term) == in.end())
                in.push_back(p.term);
        }
    }
    std::vector<int> shared;
    for (const auto &entry : termsOf) {
        const int variable = entry.first;
        if (entry.second.size() > 1)
            shared.push_back(variable);
        // What scales every term scales the whole colour (an exposure the
        // user turns in the Uniforms dock): no factor of the equation.
        if (entry.second.size() == 3
            && bindings.variables[std::size_t(variable)].variable.type == GlslType::Float)
            for (auto &term : terms)
                std::erase_if(term.second,
                              [variable](const Factor &f) { return f.variable == variable; });
    }
    int bound = bindTermColumns(bindings, reaching);
    TermBinder binder(bindings);
    for (Term term : {Term::Diffuse, Term::Specular, Term::None})
        bound += binder.bind(term, terms[term], shared);
    return bound;
}

} // namespace phonglab::usetokens
