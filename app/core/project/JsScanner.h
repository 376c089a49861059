#pragma once
#include <QByteArray>
#include <QString>

#include <string_view>
#include <utility>
#include <vector>

namespace phonglab {

// JavaScript as far as finding shader texts in it needs: tokens that know
// strings, template literals (with their ${...} parts), comments and regex
// literals, so that a quote or a backtick inside any of them is never taken
// for the start of a string. Not a parser: it never fails, and malformed
// input ends in a last token that runs to the end.

enum class JsTokenKind {
    Identifier, // names and keywords
    Number,
    String,   // '...' or "..."
    Template, // `...`, substitutions included
    Regex,
    Punctuator,
};

struct JsToken {
    JsTokenKind kind = JsTokenKind::Punctuator;
    qsizetype begin = 0; // byte offsets into the scanned text
    qsizetype end = 0;
    bool hasSubstitution = false; // a template literal with ${...}
};

std::vector<JsToken> scanJs(std::string_view js);

// A string or template literal's value, byte for byte as JavaScript reads
// it (escapes resolved, a template's CR LF read as LF), with the offset in
// the scanned text each value byte comes from. Empty for a template with
// substitutions: its value is not in the text.
struct JsStringValue {
    QByteArray value;
    std::vector<qsizetype> from; // one per byte of value
    bool known = false;
};
JsStringValue jsStringValue(std::string_view js, const JsToken &literal);

// A template literal with ${...} cut at its substitutions: the values of
// the text between them (one more part than substitutions; a part may be
// empty) and each substitution's code, [begin, end) inside its `${` `}`.
// Both empty for an unterminated literal or one that is no template.
struct JsTemplateParts {
    std::vector<JsStringValue> parts;
    std::vector<std::pair<qsizetype, qsizetype>> substitutions;
};
JsTemplateParts jsTemplateParts(std::string_view js, const JsToken &literal);

} // namespace phonglab
