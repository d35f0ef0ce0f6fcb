#pragma once
// Every problem hexc finds is a Diagnostic: a stable code, where (file:line:col and JSON path), what was expected.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hexc {

struct SourceLoc {
    std::string file;  // as given by the user (relative paths stay relative)
    int line = 0;      // 1-based; 0 when unknown
    int col = 0;       // 1-based; 0 when unknown
};

// What went wrong, as a stable code "HXnnn" a user can look up (docs/cli.md, "Diagnostic codes") and a tool can
// match on; the text around it may be reworded, the code keeps its number and meaning. HX1xx: material and scene
// files, HX2xx: templates and shader code, HX3xx: output targets, HX9xx: hexc itself.
enum class Code {
    // material and scene files
    InputUnreadable,
    JsonSyntax,
    DuplicateKey,
    UnknownKey,
    MissingKey,
    WrongType,
    OutOfRange,
    UnknownValue,
    InvalidName,
    DuplicateName,
    WrongCount,
    MisplacedKey,
    ConflictingSettings,
    UnknownReference,
    WrongSlotKind,
    InvalidSceneMaterial,
    TilingRange,
    XmlSyntax,
    MaterialXUnsupported,
    MaterialXIgnored,
    TextureNotFound,
    TextureUnreadable,
    TextureChannels,
    TextureColorSpace,
    NotPacked,
    TextureTooLarge,
    LayerRoles,
    LayerWeights,
    TextureArray,
    NotArrayed,
    NormalGreen,
    NormalTilt,
    TextureSeam,
    TextureNotFinite,
    BakeUnsupported,
    // templates and shader code
    UnknownTemplate,
    TemplateUnreadable,
    TemplateNoVersion,
    TemplateNoInclude,
    SlotNotRead,
    ShaderError,
    ShaderWarning,
    TemplateSlotLine,
    TemplateMismatch,
    TemplateTooLarge,
    TemplateSetConflict,
    // output targets
    TargetUnsupported,
    // hexc itself
    Internal,
    OutOfMemory,
};

struct Diagnostic {
    enum class Severity { Error, Warning };
    Code code;
    Severity severity;  // fixed per code, from the catalogue
    SourceLoc loc;
    std::string path;     // JSON pointer, e.g. /slots/0/falloff; empty when not about a JSON value
    std::string message;  // what is wrong and what was expected
    std::string hint;     // optional: "did you mean `rotation`?"

    // The one way to build a diagnostic: the code decides the severity.
    static Diagnostic make(Code code, SourceLoc loc, std::string path, std::string message, std::string hint = {});

    // "file:line:col: error[HX104]: /path: message (hint)"
    std::string format() const;

private:
    Diagnostic(Code c, Severity s, SourceLoc l, std::string p, std::string m, std::string h)
        : code(c), severity(s), loc(std::move(l)), path(std::move(p)), message(std::move(m)), hint(std::move(h)) {}
};

using Diagnostics = std::vector<Diagnostic>;

// One entry of the catalogue: the code, its stable name and its severity.
struct CodeInfo {
    Code code;
    std::string_view id;  // "HX104"
    Diagnostic::Severity severity;
};

// Every code, in enum order (docs/cli.md lists the same codes; a test holds the two together).
std::span<const CodeInfo> codeCatalogue();
std::string_view toString(Code code);  // its id, "HX104"

bool hasErrors(const Diagnostics& diags);
// One line each, at most 100 per file, then a line counting the rest per file. Diagnostic::make shortens a value it
// quotes (`...`) and the path to 200 bytes, saying how long they were.
std::string formatAll(const Diagnostics& diags);

// HX901 for an input of `bytes` whose reading needs more memory than the process has (a huge material under a memory
// limit): what a reader gives instead of letting std::bad_alloc end the process.
Diagnostic outOfMemoryReading(const std::string& file, uint64_t bytes);

// Thrown only by stages that cannot continue; carries the located problems.
struct CompileError {
    Diagnostics diagnostics;
};

}  // namespace hexc
