#include "hexc/diagnostics.h"

namespace hexc {

std::string Diagnostic::format() const {
    std::string out = loc.file.empty() ? std::string("hexc") : loc.file;
    if (loc.line > 0) out += ":" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
    out += severity == Severity::Error ? ": error: " : ": warning: ";
    if (!path.empty()) out += path + ": ";
    out += message;
    if (!hint.empty()) out += " (" + hint + ")";
    return out;
}

bool hasErrors(const Diagnostics& diags) {
    for (const Diagnostic& d : diags)
        if (d.severity == Diagnostic::Severity::Error) return true;
    return false;
}

std::string formatAll(const Diagnostics& diags) {
    std::string out;
    for (const Diagnostic& d : diags) out += d.format() + "\n";
    return out;
}

}  // namespace hexc
