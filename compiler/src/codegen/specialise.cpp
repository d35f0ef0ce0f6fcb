#include "codegen/specialise.h"

#include <algorithm>
#include <cstdlib>
#include <optional>

#include "common/text.h"

namespace hexc {
namespace {

// A condition's value: a bool or a number the settings give, or unknown (read at run time), with its text: an unknown's
// with what the settings decide in it folded away.
struct Value {
    enum Kind { Unknown, Bool, Number } kind = Unknown;
    double number = 0;  // a bool as 0 or 1
    std::string text;
};

std::optional<double> numberIn(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
    return v;
}

Value valueOf(const std::string& token, const Settings& settings) {
    auto it = settings.find(token);
    const std::string& text = it == settings.end() ? token : it->second;
    if (text == "true" || text == "false") return {Value::Bool, double(text == "true"), text};
    if (std::optional<double> n = numberIn(text)) return {Value::Number, *n, text};
    return {Value::Unknown, 0, text};
}

Value boolean(bool b) { return {Value::Bool, double(b), b ? "true" : "false"}; }

// Recursive descent over a condition's tokens: || over && over ! over comparisons of operands (a setting, a literal or
// a parenthesised condition). Anything else in it (arithmetic, a call, an index) makes it undecided.
class Condition {
public:
    Condition(std::string_view text, const Settings& settings) : settings_(settings) { tokenize(text); }

    // nullopt when the condition is not one this reads.
    std::optional<Value> evaluate() {
        Value v = either();
        return ok_ && at_ == tokens_.size() ? std::optional<Value>(v) : std::nullopt;
    }

private:
    void tokenize(std::string_view text) {
        for (size_t i = 0; i < text.size();) {
            if (text[i] == ' ') {
                ++i;
                continue;
            }
            size_t end = i;
            while (end < text.size() && (isIdentifierChar(text[end]) || text[end] == '.')) ++end;
            if (end == i) end = i + (text.substr(i, 2) == "&&" || text.substr(i, 2) == "||" || text.substr(i + 1, 1) == "=" ? 2 : 1);
            tokens_.emplace_back(text.substr(i, end - i));
            i = end;
        }
    }
    bool take(std::string_view token) {
        if (at_ < tokens_.size() && tokens_[at_] == token) return ++at_, true;
        return false;
    }
    // a || b, and below a && b: decided by one decided operand (true for ||, false for &&) or by all; an operand that
    // does not decide it drops out of its text.
    Value either() {
        Value v = both();
        while (take("||")) v = combine(v, both(), true);
        return v;
    }
    Value both() {
        Value v = negation();
        while (take("&&")) v = combine(v, negation(), false);
        return v;
    }
    static Value combine(const Value& a, const Value& b, bool orElse) {
        const double wins = orElse ? 1 : 0;
        if ((a.kind == Value::Bool && a.number == wins) || (b.kind == Value::Bool && b.number == wins)) return boolean(wins);
        if (a.kind == Value::Bool && b.kind == Value::Bool) return boolean(!wins);
        if (a.kind == Value::Bool) return b;
        if (b.kind == Value::Bool) return a;
        return {Value::Unknown, 0, a.text + (orElse ? " || " : " && ") + b.text};
    }
    Value negation() {
        if (!take("!")) return comparison();
        Value v = negation();
        if (v.kind == Value::Bool) return boolean(!v.number);
        return {Value::Unknown, 0, "!" + (v.text.find(' ') == std::string::npos ? v.text : "(" + v.text + ")")};
    }
    Value comparison() {
        Value a = operand();
        static const char* kOps[] = {"==", "!=", "<=", ">=", "<", ">"};
        for (const char* op : kOps) {
            if (!take(op)) continue;
            Value b = operand();
            if (a.kind == Value::Unknown || a.kind != b.kind) return {Value::Unknown, 0, a.text + " " + op + " " + b.text};
            const double x = a.number, y = b.number;
            const std::string_view o = op;
            return boolean(o == "==" ? x == y : o == "!=" ? x != y : o == "<=" ? x <= y : o == ">=" ? x >= y : o == "<" ? x < y : x > y);
        }
        return a;
    }
    Value operand() {
        if (take("(")) {
            Value v = either();
            ok_ = ok_ && take(")");
            if (v.kind == Value::Unknown) v.text = "(" + v.text + ")";
            return v;
        }
        if (at_ >= tokens_.size() || !(isIdentifierChar(tokens_[at_][0]))) {
            ok_ = false;
            return {};
        }
        return valueOf(tokens_[at_++], settings_);
    }

    const Settings& settings_;
    std::vector<std::string> tokens_;
    size_t at_ = 0;
    bool ok_ = true;
};

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

// The first `ch` of `text` from `from` on outside brackets; for ':' the one that closes the `?` before `from`.
size_t topLevel(std::string_view text, size_t from, char ch) {
    int depth = 0, open = 0;
    for (size_t i = from; i < text.size(); ++i) {
        const char c = text[i];
        depth += c == '(' || c == '[' ? 1 : c == ')' || c == ']' ? -1 : 0;
        if (depth != 0) continue;
        if (c == ch && open == 0) return i;
        open += c == '?' ? 1 : c == ':' ? -1 : 0;
    }
    return std::string_view::npos;
}

// `code` with a statement `... = c ? x : y;` or `return c ? x : y;` whose condition the settings decide as x or y; one
// they leave open keeps what of it they do not decide.
std::string foldSelect(const std::string& code, const Settings& settings) {
    const std::string_view t = trimmed(code);
    size_t start = t.starts_with("return ") ? 6 : std::string_view::npos;
    for (size_t i = 1; start == std::string_view::npos && i + 1 < t.size(); ++i)
        if (t[i] == '=' && t[i + 1] != '=' && std::string_view("=!<>").find(t[i - 1]) == std::string_view::npos) start = i + 1;
    const size_t end = t.rfind(';');
    if (start == std::string_view::npos || end == std::string_view::npos) return code;
    const size_t question = topLevel(t.substr(0, end), start, '?');
    if (question == std::string_view::npos) return code;
    const Decision d = decide(t.substr(start, question - start), settings);
    const size_t colon = topLevel(t.substr(0, end), question + 1, ':');
    const size_t indent = code.find_first_not_of(' ');
    const std::string head = code.substr(0, indent) + std::string(t.substr(0, start)) + " ";
    if (d.taken < 0 && !d.rest.empty()) return head + d.rest + " " + std::string(t.substr(question));
    if (d.taken < 0 || colon == std::string_view::npos) return code;
    const std::string_view branch = d.taken ? t.substr(question + 1, colon - question - 1) : t.substr(colon + 1, end - colon - 1);
    return head + std::string(trimmed(branch)) + std::string(t.substr(end));
}

// Each read of a setting (`l.field`, `b.field`, not itself a member of something) replaced by its value.
std::string substitute(const std::string& code, const Settings& settings) {
    std::string out;
    size_t copied = 0;
    for (std::string_view word : identifiers(code)) {
        const size_t at = size_t(word.data() - code.data());
        if ((word != "l" && word != "b") || (at > 0 && code[at - 1] == '.') || at + 1 >= code.size() || code[at + 1] != '.') continue;
        size_t end = at + 2;
        while (end < code.size() && isIdentifierChar(code[end])) ++end;
        auto it = settings.find(code.substr(at, end - at));
        if (it == settings.end()) continue;
        out.append(code, copied, at - copied).append(it->second);
        copied = end;
    }
    return out.append(code, copied);
}

class Specialiser {
public:
    explicit Specialiser(const Settings& settings) : settings_(settings) {}
    std::vector<SourceLine> out;

    // Lines [begin, end) of `in`, `dedent` spaces less indented.
    void lines(const std::vector<SourceLine>& in, size_t begin, size_t end, size_t dedent) {
        for (size_t i = begin; i < end; ++i) {
            const std::string& text = in[i].text;
            const size_t indent = text.find_first_not_of(' ');
            if (indent != std::string::npos && text.compare(indent, 4, "if (") == 0) {
                if (size_t next = branch(in, i, end, dedent); next != i) {
                    i = next - 1;
                    continue;
                }
            }
            line(in[i], dedent);
        }
    }

private:
    void line(const SourceLine& l, size_t dedent) {
        const size_t cut =
            std::min(dedent, l.text.find_first_not_of(' ') == std::string::npos ? l.text.size() : l.text.find_first_not_of(' '));
        const std::string text = l.text.substr(cut);
        const size_t code = codeOf(text).size();
        out.push_back({l.number, substitute(foldSelect(text.substr(0, code), settings_), settings_) + text.substr(code)});
    }

    // The `if` at line i when the settings decide it: its branch taken emitted, the index past it returned. One they leave
    // open: the line with what of its condition they do not decide, i + 1. Else i.
    size_t branch(const std::vector<SourceLine>& in, size_t i, size_t end, size_t dedent) {
        const std::string code(codeOf(in[i].text));
        const size_t indent = code.find_first_not_of(' '), open = indent + 3, close = closingBracket(code, open);
        if (close == std::string::npos) return i;
        const auto [taken, undecided] = decide(std::string_view(code).substr(open + 1, close - open - 2), settings_);
        if (taken < 0 && !undecided.empty()) {
            line({in[i].number, code.substr(0, open + 1) + undecided + in[i].text.substr(close - 1)}, dedent);
            return i + 1;
        }
        const std::string rest(trimmed(std::string_view(code).substr(close)));
        if (taken < 0 || rest.empty()) return i;
        if (rest != "{") {  // `if (c) statement;`
            if (taken) line({in[i].number, code.substr(0, indent) + rest}, dedent);
            return i + 1;
        }
        const std::string ind = code.substr(0, indent);
        size_t j = i + 1;
        while (j < end && !(in[j].text.starts_with(ind + "}"))) ++j;
        const bool otherwise = j < end && in[j].text == ind + "} else {";
        size_t k = j + 1;
        while (otherwise && k < end && in[k].text != ind + "}") ++k;
        if (j == end || (in[j].text != ind + "}" && !otherwise) || (otherwise && k == end)) return i;  // e.g. `else if`: as it is
        if (taken) lines(in, i + 1, j, dedent + 4);
        if (!taken && otherwise) lines(in, j + 1, k, dedent + 4);
        return otherwise ? k + 1 : j + 1;
    }

    const Settings& settings_;
};

}  // namespace

Decision decide(std::string_view condition, const Settings& settings) {
    const std::optional<Value> v = Condition(condition, settings).evaluate();
    if (!v) return {};
    if (v->kind == Value::Bool) return {int(v->number), ""};
    return {-1, v->text};
}

std::vector<SourceLine> specialise(const std::vector<SourceLine>& lines, const Settings& settings) {
    Specialiser s(settings);
    s.lines(lines, 0, lines.size(), 0);
    return std::move(s.out);
}

}  // namespace hexc
