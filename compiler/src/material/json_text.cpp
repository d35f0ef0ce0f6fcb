#include "hexc/json_text.h"

#include <algorithm>
#include <vector>

#include "material/json_locator.h"

namespace hexc {

namespace {

using Json = nlohmann::ordered_json;

// A value written for a member or element the text does not have, in the examples' style: `{ "a": 1 }`, `[4, 4]`.
std::string written(const Json& value) {
    if (value.is_object()) {
        if (value.empty()) return "{}";
        std::string out = "{ ";
        for (auto it = value.begin(); it != value.end(); ++it)
            out += (it == value.begin() ? "" : ", ") + Json(it.key()).dump() + ": " + written(it.value());
        return out + " }";
    }
    if (value.is_array()) {
        std::string out = "[";
        for (size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + written(value[i]);
        return out + "]";
    }
    return value.dump();
}

// Whether `value` has more than `limit` levels of arrays and objects, walked without recursion.
bool deeperThan(const Json& value, int limit) {
    std::vector<std::pair<const Json*, int>> todo{{&value, 1}};
    while (!todo.empty()) {
        auto [v, depth] = todo.back();
        todo.pop_back();
        if (!v->is_structured()) continue;
        if (depth > limit) return true;
        for (const Json& child : *v) todo.push_back({&child, depth + 1});
    }
    return false;
}

class Rewriter {
public:
    explicit Rewriter(std::string_view text) : text_(text), locator_(text) {}

    // The whole text, its root value made to hold `edited`: what stands around it (a byte order mark, the last
    // newline) stays.
    std::string document(const Json& original, const Json& edited) const {
        const JsonLocator::Span root = *locator_.valueSpan("");
        return slice(0, root.begin) + value("", original, edited) + slice(root.end, text_.size());
    }

    // The text of the value at `pointer`, which is `original` in the text, made to hold `edited`.
    std::string value(const std::string& pointer, const Json& original, const Json& edited) const {
        const JsonLocator::Span span = *locator_.valueSpan(pointer);
        if (original == edited) return slice(span.begin, span.end);
        if (original.is_object() && edited.is_object()) return object(pointer, span, original, edited);
        if (original.is_array() && edited.is_array() && original.size() == edited.size()) {
            std::vector<Child> children;
            for (size_t i = 0; i < original.size(); ++i) children.push_back({pointerAppend(pointer, i), original[i], edited[i]});
            return inPlace(span, children);
        }
        return written(edited);
    }

private:
    std::string slice(size_t from, size_t to) const { return std::string(text_.substr(from, to - from)); }

    struct Child {
        std::string pointer;
        const Json& original;
        const Json& edited;
    };
    // The text of `span` with each child's value made to hold its edit, and what stands between them as written.
    std::string inPlace(JsonLocator::Span span, const std::vector<Child>& children) const {
        std::string out;
        size_t at = span.begin;
        for (const Child& c : children) {
            const JsonLocator::Span s = *locator_.valueSpan(c.pointer);
            out += slice(at, s.begin) + value(c.pointer, c.original, c.edited);
            at = s.end;
        }
        return out + slice(at, span.end);
    }

    // An object: with the same keys in the same order, only its members' values change, between the text's own
    // spacing; else its members are laid out again in `edited`'s order, each kept one as written, with the spacing
    // the text has between its members.
    std::string object(const std::string& pointer, JsonLocator::Span span, const Json& original, const Json& edited) const {
        std::vector<std::string> keys, editedKeys;
        for (auto it = original.begin(); it != original.end(); ++it) keys.push_back(it.key());
        for (auto it = edited.begin(); it != edited.end(); ++it) editedKeys.push_back(it.key());
        if (keys == editedKeys) {
            std::vector<Child> children;
            for (const std::string& key : keys) children.push_back({pointerAppend(pointer, key), original[key], edited[key]});
            return inPlace(span, children);
        }
        if (edited.empty()) return "{}";
        std::string open = "{ ", between = ", ", close = " }";
        if (!keys.empty()) {
            const size_t first = *locator_.keyOffset(pointerAppend(pointer, keys.front()));
            const size_t lastEnd = locator_.valueSpan(pointerAppend(pointer, keys.back()))->end;
            open = slice(span.begin, first);
            close = slice(lastEnd, span.end);
            between = keys.size() > 1 ? slice(locator_.valueSpan(pointerAppend(pointer, keys[0]))->end,
                                              *locator_.keyOffset(pointerAppend(pointer, keys[1])))
                                      : "," + open.substr(1);
        }
        std::string out = open;
        for (auto it = edited.begin(); it != edited.end(); ++it) {
            if (it != edited.begin()) out += between;
            const std::string child = pointerAppend(pointer, it.key());
            if (original.contains(it.key()))
                out += slice(*locator_.keyOffset(child), locator_.valueSpan(child)->begin) + value(child, original[it.key()], it.value());
            else
                out += Json(it.key()).dump() + ": " + written(it.value());
        }
        return out + close;
    }

    std::string_view text_;
    JsonLocator locator_;
};

}  // namespace

bool nestsTooDeep(std::string_view text) { return excessiveNesting(text).has_value(); }

std::optional<std::string> rewriteJsonText(std::string_view text, const nlohmann::ordered_json& edited, std::string* whyNot) {
    auto fail = [&](const std::string& why) -> std::optional<std::string> {
        if (whyNot) *whyNot = why;
        return std::nullopt;
    };
    if (excessiveNesting(text) || deeperThan(edited, kMaxJsonDepth))
        return fail("it nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    Json original = Json::parse(text, nullptr, false);
    if (original.is_discarded()) return fail("it is not JSON");
    std::string out = Rewriter(text).document(original, edited);
    // What the rewrite must give, checked rather than trusted: a text it cannot keep is refused, never written wrong.
    if (Json::parse(out, nullptr, false) != edited) return fail("hexc could not keep its text (a duplicate key?)");
    return out;
}

}  // namespace hexc
