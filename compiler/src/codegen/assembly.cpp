#include "codegen/assembly.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>

#include "codegen/array_forms.h"

namespace hexc {
namespace {

// `text` with the identifiers of its code that `to` renames replaced, from the last to the first, each call's arguments
// at the positions `to` gives taken out (a call to a library piece ends on its line).
std::string renameIn(const std::string& text, const std::function<std::optional<PieceName>(std::string_view)>& to) {
    std::string out = text;
    const std::vector<std::string_view> words = identifiers(codeOf(text));
    for (auto word = words.rbegin(); word != words.rend(); ++word) {
        std::optional<PieceName> n = to(*word);
        if (!n) continue;
        const size_t at = size_t(word->data() - text.data());
        size_t end = at + word->size();
        std::string replacement = n->name;
        if (!n->dropped.empty()) {
            const size_t open = out.find_first_not_of(' ', end);
            const size_t close = open == std::string::npos || out[open] != '(' ? std::string::npos : closingBracket(out, open);
            if (close == std::string::npos) throw std::logic_error("hexc library: a call to `" + std::string(*word) + "` beyond its line");
            const std::vector<std::string> args = splitList(std::string_view(out).substr(open + 1, close - open - 2));
            std::string kept;
            for (size_t i = 0; i < args.size(); ++i)
                if (std::find(n->dropped.begin(), n->dropped.end(), i) == n->dropped.end()) kept += (kept.empty() ? "" : ", ") + args[i];
            replacement += "(" + kept + ")";
            end = close;
        }
        out.replace(at, end - at, replacement);
    }
    return out;
}

// The index in `lines` of the definition of `p` (after the comment above it).
size_t definitionOf(const std::vector<SourceLine>& lines, const Piece& p) {
    auto definition = std::find_if(lines.begin(), lines.end(), [&](const SourceLine& l) {
        return !l.text.empty() && l.text[0] != ' ' && l.text[0] != '/' && codeOf(l.text).find(p.name + "(") != std::string_view::npos;
    });
    if (definition == lines.end()) throw std::logic_error("hexc library: no definition of " + p.name);
    return size_t(definition - lines.begin());
}

// Takes the parameters `HexcLattice l` and `HexcBlend b` out of `definition` where `body` no longer reads them (the
// settings it read are values now, and its callees take them no more); returns their positions.
std::vector<size_t> withoutSettings(SourceLine& definition, const std::vector<SourceLine>& body) {
    std::string read;  // the one-letter names the body reads: `l`, `b`, or a local of that name, which keeps a parameter
    for (const SourceLine& line : body)
        for (std::string_view word : identifiers(codeOf(line.text)))
            if (word.size() == 1 && line.text[size_t(word.data() - line.text.data()) - 1] != '.') read += word;
    std::string& text = definition.text;
    const size_t open = text.find('('), close = closingBracket(text, open);
    const std::vector<std::string> params = splitList(std::string_view(text).substr(open + 1, close - open - 2));
    std::vector<size_t> dropped;
    std::string kept;
    for (size_t i = 0; i < params.size(); ++i) {
        const bool unread =
            (params[i] == "HexcLattice l" || params[i] == "HexcBlend b") && read.find(params[i].back()) == std::string::npos;
        if (unread) dropped.push_back(i);
        if (!unread) kept += (kept.empty() ? "" : ", ") + params[i];
    }
    text.replace(open, close - open, "(" + kept + ")");
    return dropped;
}

}  // namespace

std::string Assembly::use(const std::string& text, const Settings* settings, const std::string& slot) {
    std::vector<SourceLine> lines;
    for (size_t begin = 0; begin <= text.size();) {
        const size_t end = std::min(text.find('\n', begin), text.size());
        lines.push_back({0, text.substr(begin, end - begin)});
        begin = end + 1;
    }
    std::string out;
    for (const SourceLine& l : renamed(lines, SIZE_MAX, settings, slot)) out += l.text + "\n";
    out.pop_back();
    return out;
}

std::vector<SourceLine> Assembly::renamed(const std::vector<SourceLine>& lines, size_t self, const Settings* settings,
                                          const std::string& slot) {
    const Library& lib = library();
    std::vector<SourceLine> out = lines;
    for (SourceLine& line : out) {
        if (line.text.find("exc") == std::string::npos) continue;  // names no piece: they all start with hexc or Hexc
        line.text = renameIn(line.text, [&](std::string_view word) -> std::optional<PieceName> {
            auto it = lib.byName.find(word);
            if (it == lib.byName.end() || it->second == self) return std::nullopt;
            if (!settings) {
                useGeneral(it->second);
                return std::nullopt;
            }
            PieceName n = form(it->second, settings, slot);
            return n.name == word && n.dropped.empty() ? std::nullopt : std::optional<PieceName>(n);
        });
    }
    return out;
}

void Assembly::useGeneral(size_t piece) {
    if (general_[piece]) return;
    general_[piece] = true;
    for (size_t used : library().pieces[piece].uses) useGeneral(used);
}

PieceName Assembly::form(size_t piece, const Settings* settings, const std::string& slot) {
    if (auto it = names_.find({piece, slot}); it != names_.end()) return it->second;
    const Piece& p = library().pieces[piece];
    Settings own;  // only those of the settings structs the piece takes: `b` may name something else elsewhere
    for (const auto& [key, value] : *settings)
        if ((key.starts_with("l.") && p.lattice) || (key.starts_with("b.") && p.blend)) own.emplace(key, value);
    std::vector<SourceLine> lines = own.empty() ? p.lines : specialise(p.lines, own);
    if (auto layer = settings->find(kArrayLayer); layer != settings->end()) lines = inArray(lines, layer->second);
    // The body first: its calls drop the settings their callees no longer take; then a specialised definition drops
    // those it no longer reads, and only then names the types of the parameters it keeps (an unused settings struct is
    // left out).
    const size_t head = own.empty() ? 0 : definitionOf(lines, p) + 1;
    std::vector<SourceLine> body = renamed({lines.begin() + head, lines.end()}, piece, settings, slot);
    lines.resize(head);
    const std::vector<size_t> dropped = own.empty() ? std::vector<size_t>() : withoutSettings(lines.back(), body);
    lines = renamed(lines, piece, settings, slot);
    lines.insert(lines.end(), body.begin(), body.end());
    PieceName& name = names_[{piece, slot}];
    if (lines == p.lines) {
        useGeneral(piece);
        return name = {p.name, {}};
    }
    std::string key;
    for (const SourceLine& l : lines) key += std::to_string(l.number) + " " + l.text + "\n";
    std::vector<Form>& forms = forms_[piece];
    for (const Form& f : forms)
        if (f.key == key) return name = f.name;
    Form f{{p.name + "_" + slot, dropped}, key, lines};
    for (SourceLine& l : f.lines)
        l.text = renameIn(l.text, [&](std::string_view word) {
            return word == p.name ? std::optional<PieceName>(PieceName{f.name.name, {}}) : std::nullopt;
        });
    forms.push_back(std::move(f));
    return name = forms.back().name;
}

std::string Assembly::text() const {
    const Library& lib = library();
    std::string out;
    auto emit = [&out](const std::vector<SourceLine>& lines, const std::string& file) {
        int previous = -1;
        for (const SourceLine& l : lines) {
            if (l.number != previous + 1) out += "#line " + std::to_string(l.number) + " \"" + file + "\"\n";
            out += l.text + "\n";
            previous = l.number;
        }
        out += "\n";
    };
    for (size_t i = 0; i < lib.pieces.size(); ++i) {
        if (auto it = general_.find(i); it != general_.end() && it->second) emit(lib.pieces[i].lines, lib.pieces[i].file);
        if (auto it = forms_.find(i); it != forms_.end())
            for (const Form& f : it->second) emit(f.lines, lib.pieces[i].file);
    }
    return out;
}

}  // namespace hexc
