#include "hexc/diagnostics.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <tuple>

#include "hexc/report.h"

namespace hexc {
namespace {

using enum Diagnostic::Severity;

// The catalogue. An id, once released, is never reused for another meaning; new codes take the next free number
// of their group. docs/cli.md explains each one. One code a line, whatever the table's length (clang-format would
// pack them into columns).
// clang-format off
constexpr CodeInfo kCatalogue[] = {
    {Code::InputUnreadable, "HX100", Error},
    {Code::JsonSyntax, "HX101", Error},
    {Code::DuplicateKey, "HX102", Error},
    {Code::UnknownKey, "HX103", Error},
    {Code::MissingKey, "HX104", Error},
    {Code::WrongType, "HX105", Error},
    {Code::OutOfRange, "HX106", Error},
    {Code::UnknownValue, "HX107", Error},
    {Code::InvalidName, "HX108", Error},
    {Code::DuplicateName, "HX109", Error},
    {Code::WrongCount, "HX110", Error},
    {Code::MisplacedKey, "HX111", Error},
    {Code::ConflictingSettings, "HX112", Error},
    {Code::UnknownReference, "HX113", Error},
    {Code::WrongSlotKind, "HX114", Error},
    {Code::InvalidSceneMaterial, "HX115", Error},
    {Code::TilingRange, "HX116", Warning},
    {Code::XmlSyntax, "HX117", Error},
    {Code::MaterialXUnsupported, "HX118", Error},
    {Code::MaterialXIgnored, "HX119", Warning},
    {Code::TextureNotFound, "HX120", Error},
    {Code::TextureUnreadable, "HX121", Error},
    {Code::TextureChannels, "HX122", Error},
    {Code::TextureColorSpace, "HX123", Warning},
    {Code::NotPacked, "HX124", Warning},
    {Code::TextureTooLarge, "HX125", Error},
    {Code::LayerRoles, "HX126", Error},
    {Code::LayerWeights, "HX127", Error},
    {Code::TextureArray, "HX128", Error},
    {Code::NotArrayed, "HX129", Warning},
    {Code::NormalGreen, "HX130", Warning},
    {Code::NormalTilt, "HX131", Warning},
    {Code::TextureSeam, "HX132", Warning},
    {Code::TextureNotFinite, "HX133", Warning},
    {Code::BakeUnsupported, "HX134", Error},
    {Code::UnknownTemplate, "HX200", Error},
    {Code::TemplateUnreadable, "HX201", Error},
    {Code::TemplateNoVersion, "HX202", Error},
    {Code::TemplateNoInclude, "HX203", Error},
    {Code::SlotNotRead, "HX204", Warning},
    {Code::ShaderError, "HX205", Error},
    {Code::ShaderWarning, "HX206", Warning},
    {Code::TemplateSlotLine, "HX207", Error},
    {Code::TemplateMismatch, "HX208", Error},
    {Code::TemplateTooLarge, "HX209", Error},
    {Code::TemplateSetConflict, "HX210", Error},
    {Code::TargetUnsupported, "HX300", Error},
    {Code::Internal, "HX900", Error},
    {Code::OutOfMemory, "HX901", Error},
};
// clang-format on

// Indexed by the enum: every code has its entry, in order.
constexpr bool inEnumOrder() {
    for (size_t i = 0; i < std::size(kCatalogue); ++i)
        if (kCatalogue[i].code != Code(i)) return false;
    return true;
}
static_assert(inEnumOrder() && std::size(kCatalogue) == size_t(Code::OutOfMemory) + 1, "kCatalogue must list every Code in enum order");

// A value a diagnostic quotes back (a name, a key, a JSON path) is shown up to this many bytes: a 60 MB name is the
// input's mistake, not something to print whole.
constexpr size_t kMaxQuoted = 200;
// Diagnostics printed per file: the first ones show what is wrong; thousands more from one generated file would bury
// them and take the terminal's time.
constexpr size_t kMaxPerFile = 100;

// `text` cut to kMaxQuoted bytes (not inside a UTF-8 character) with the length it had.
std::string shortened(std::string_view text) {
    if (text.size() <= kMaxQuoted) return std::string(text);
    size_t end = kMaxQuoted;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
    return std::string(text.substr(0, end)) + "... (" + std::to_string(text.size()) + " bytes)";
}

// Every `quoted` or "quoted" span of the message shortened.
std::string withQuotesShortened(const std::string& message) {
    if (message.size() <= kMaxQuoted) return message;
    std::string out;
    size_t at = 0;
    for (size_t open; (open = message.find_first_of("`\"", at)) != std::string::npos;) {
        const size_t close = message.find(message[open], open + 1);
        if (close == std::string::npos) break;
        out += message.substr(at, open + 1 - at) + shortened(std::string_view(message).substr(open + 1, close - open - 1)) + message[open];
        at = close + 1;
    }
    return out + message.substr(at);
}

}  // namespace

std::span<const CodeInfo> codeCatalogue() { return kCatalogue; }

std::string_view toString(Code code) { return kCatalogue[size_t(code)].id; }

Diagnostic Diagnostic::make(Code code, SourceLoc loc, std::string path, std::string message, std::string hint) {
    return Diagnostic(code, kCatalogue[size_t(code)].severity, std::move(loc), shortened(path), withQuotesShortened(message),
                      withQuotesShortened(hint));
}

std::string Diagnostic::format() const {
    std::string out = loc.file.empty() ? std::string("hexc") : loc.file;
    if (loc.line > 0) out += ":" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
    out += severity == Severity::Error ? ": error[" : ": warning[";
    out += std::string(toString(code)) + "]: ";
    if (!path.empty()) out += path + ": ";
    out += message;
    if (!hint.empty()) out += " (" + hint + ")";
    return out;
}

Diagnostics byPosition(Diagnostics diags) {
    std::map<std::string, size_t> files;
    for (const Diagnostic& d : diags) files.emplace(d.loc.file, files.size());
    std::stable_sort(diags.begin(), diags.end(), [&files](const Diagnostic& a, const Diagnostic& b) {
        return std::tuple(files.at(a.loc.file), a.loc.line, a.loc.col) < std::tuple(files.at(b.loc.file), b.loc.line, b.loc.col);
    });
    return diags;
}

bool hasErrors(const Diagnostics& diags) {
    for (const Diagnostic& d : diags)
        if (d.severity == Diagnostic::Severity::Error) return true;
    return false;
}

Diagnostic outOfMemoryReading(const std::string& file, uint64_t bytes) {
    return Diagnostic::make(
        Code::OutOfMemory, {file}, "",
        "out of memory reading this document (" + std::to_string(bytes >> 20) + " MiB): it needs more memory than this process has");
}

std::string formatAll(const Diagnostics& diags) {
    std::string out;
    std::map<std::string, size_t> shown, hidden;  // per file
    for (const Diagnostic& d : diags)
        if (shown[d.loc.file] < kMaxPerFile)
            out += d.format() + "\n", ++shown[d.loc.file];
        else
            ++hidden[d.loc.file];
    for (const auto& [file, count] : hidden)
        out += (file.empty() ? "hexc" : file) + ": " + std::to_string(count) + " more diagnostics not shown (the first " +
               std::to_string(kMaxPerFile) + " are)\n";
    return out;
}

}  // namespace hexc
