// Slot names of MaterialX shader inputs (materialx_names.h).
#include "material/materialx_names.h"

namespace hexc::mtlx {

std::string slotName(std::string_view shader, std::string_view input) {
    for (const SlotInput& s : kSlotInputs)
        if (s.shader == shader && s.input == input) return std::string(s.slot);
    std::string out;
    for (size_t i = 0; i < input.size(); ++i) {
        char c = input[i];
        if (c >= 'A' && c <= 'Z') {
            const char before = i ? input[i - 1] : '_';
            if ((before >= 'a' && before <= 'z') || (before >= '0' && before <= '9')) out += '_';
            c = char(c - 'A' + 'a');
        }
        out += c;
    }
    return out;
}

void uniqueSlotNames(nlohmann::json& slots) {
    auto clash = [](const std::string& a, const std::string& b) { return a == b || a.starts_with(b + "_") || b.starts_with(a + "_"); };
    auto name = [&](size_t i) { return slots[i]["name"].get<std::string>(); };
    for (size_t i = 0; i < slots.size(); ++i) {
        auto clashes = [&](const std::string& n, bool renaming) {
            for (size_t j = 0; j < slots.size(); ++j)
                if (j != i && clash(n, name(j)) && (!renaming || name(j).size() > n.size() || (name(j) == n && j < i))) return true;
            return false;
        };
        if (!clashes(name(i), true)) continue;
        std::string renamed;
        for (int k = 2; clashes(renamed = name(i) + std::to_string(k), false); ++k) {
        }
        slots[i]["name"] = renamed;
    }
}

}  // namespace hexc::mtlx
