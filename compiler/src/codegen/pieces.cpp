#include "codegen/pieces.h"

#include <algorithm>
#include <stdexcept>

#include "common/templates.h"
#include "common/text.h"

namespace hexc {
namespace {

// The name a top-level line declares: `struct Name {`, `const type name = ...;` or `type name(...`.
std::string declaredName(std::string_view line) {
    std::vector<std::string_view> words = identifiers(codeOf(line));
    if (words.size() >= 2 && (words[0] == "struct" || words[0] == "const")) return std::string(words[words[0] == "const" ? 2 : 1]);
    const size_t open = line.find('(');
    if (open == std::string_view::npos || words.size() < 2) throw std::logic_error("hexc library: no name in `" + std::string(line) + "`");
    return std::string(identifiers(line.substr(0, open)).back());
}

// Appends the pieces of one library file. A piece starts at a line of code at column 0 and ends there, or at the next
// `}` at column 0 when the line opens a brace it does not close; the comment lines right above it are its own.
void addPieces(const std::string& text, const std::string& file, std::vector<Piece>& out) {
    std::vector<SourceLine> comment;
    Piece* open = nullptr;
    int number = 0;
    for (size_t begin = 0; begin < text.size(); ++number) {
        size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        SourceLine line{number + 1, text.substr(begin, end - begin)};
        begin = end + 1;
        if (open) {
            open->lines.push_back(line);
            if (line.text.starts_with("}")) open = nullptr;
            continue;
        }
        if (line.text.starts_with("//")) comment.push_back(std::move(line));
        if (line.text.empty() || line.text[0] == ' ' || line.text.starts_with("//")) {
            if (line.text.empty()) comment.clear();
            continue;
        }
        const std::string name = declaredName(line.text);
        const bool overload = !out.empty() && out.back().name == name;  // kept together: one name, one piece
        if (!overload) out.push_back({name, file, {}, false, false, {}});
        Piece& piece = out.back();
        piece.lines.insert(piece.lines.end(), comment.begin(), comment.end());
        comment.clear();
        const std::string_view code = codeOf(line.text);
        const bool closes = std::count(code.begin(), code.end(), '{') == std::count(code.begin(), code.end(), '}');
        piece.lines.push_back(std::move(line));
        if (!closes) open = &piece;
    }
}

// The fields of struct piece `s` and the arguments of `return <name>(...);` in its neutral constructor `c`.
std::vector<std::pair<std::string, std::string>> neutralValues(const Piece& s, const Piece& c) {
    std::vector<std::string> values;
    for (const SourceLine& line : c.lines)
        if (size_t at = line.text.find("return " + s.name + "("); at != std::string::npos) {
            const size_t open = line.text.find('(', at);
            values = splitList(std::string_view(line.text).substr(open + 1, closingBracket(line.text, open) - open - 2));
        }
    std::vector<std::pair<std::string, std::string>> out;
    for (const SourceLine& line : s.lines) {
        const std::vector<std::string_view> words = identifiers(codeOf(line.text));
        if (line.text.starts_with("    ") && words.size() == 2 && out.size() < values.size())
            out.emplace_back(words[1], values[out.size()]);
    }
    if (out.size() != values.size()) throw std::logic_error("hexc library: " + c.name + "() does not give every field of " + s.name);
    return out;
}

}  // namespace

size_t closingBracket(std::string_view text, size_t open) {
    int depth = 0;
    for (size_t i = open; i < text.size(); ++i) {
        depth += text[i] == '(' || text[i] == '[' ? 1 : text[i] == ')' || text[i] == ']' ? -1 : 0;
        if (depth == 0) return i + 1;
    }
    return std::string_view::npos;
}

std::vector<std::string> splitList(std::string_view list) {
    std::vector<std::string> out;
    int depth = 0;
    size_t start = 0;
    auto add = [&](size_t end) {
        std::string_view item = list.substr(start, end - start);
        while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
        while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
        out.emplace_back(item);
    };
    for (size_t i = 0; i < list.size(); ++i) {
        depth += list[i] == '(' || list[i] == '[' ? 1 : list[i] == ')' || list[i] == ']' ? -1 : 0;
        if (list[i] == ',' && depth == 0) add(i), start = i + 1;
    }
    if (list.find_first_not_of(' ') != std::string_view::npos) add(list.size());
    return out;
}

std::string_view codeOf(std::string_view text) {
    const size_t comment = text.find("//");
    return comment == std::string_view::npos ? text : text.substr(0, comment);
}

std::vector<std::string_view> identifiers(std::string_view text) {
    std::vector<std::string_view> out;
    for (size_t i = 0; i < text.size();) {
        if (!isIdentifierChar(text[i])) {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < text.size() && isIdentifierChar(text[end])) ++end;
        if (text[i] < '0' || text[i] > '9') out.push_back(text.substr(i, end - i));  // a number's letters (2u, 1e5) are not one
        i = end;
    }
    return out;
}

const Library& library() {
    static const Library parsed = [] {
        Library out;
        addPieces(*embeddedText("hextiling.glsl"), "hexc/hextiling.glsl", out.pieces);
        addPieces(*embeddedText("materialx.glsl"), "hexc/materialx.glsl", out.pieces);
        for (size_t i = 0; i < out.pieces.size(); ++i) {
            Piece& p = out.pieces[i];
            out.byName[p.name] = i;
            for (const SourceLine& line : p.lines) {
                const std::string_view code = codeOf(line.text);
                for (std::string_view word : identifiers(code))
                    if (auto it = out.byName.find(word); it != out.byName.end() && it->second != i) p.uses.push_back(it->second);
                p.lattice = p.lattice || code.find("HexcLattice l,") != code.npos || code.find("HexcLattice l)") != code.npos;
                p.blend = p.blend || code.find("HexcBlend b,") != code.npos || code.find("HexcBlend b)") != code.npos;
            }
        }
        for (const char* settings : {"HexcLattice", "HexcBlend"}) {
            const Piece& s = out.pieces.at(out.byName.at(settings));
            out.neutral[settings] = neutralValues(s, out.pieces.at(out.byName.at("hexc" + s.name.substr(4))));
        }
        return out;
    }();
    return parsed;
}

}  // namespace hexc
