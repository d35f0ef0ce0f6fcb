#include "spirv/textures.h"

#include <algorithm>
#include <bit>
#include <set>
#include <stdexcept>

#include "spirv/module.h"
#include "spirv/strings.h"

namespace hexc {
namespace {

using spirv::Instruction;
using spirv::instruction;
using spirv::Module;

void appendId(Instruction& i, uint32_t id) {
    i.words.push_back(id);
    i.ids.push_back(uint16_t(i.words.size() - 1));
    i.words[0] += 1u << spv::WordCountShift;
}

// What texturesAsParameters reads of a module: its UniformConstant variables, names, entry points, and each
// function's direct reads of those variables and its calls.
struct Reads {
    std::vector<uint32_t> variables;           // in declaration order
    std::map<uint32_t, uint32_t> pointerType;  // variable -> its type
    std::map<uint32_t, std::string> names;
    std::set<uint32_t> entries;
    std::map<uint32_t, std::set<uint32_t>> direct;
    std::map<uint32_t, std::vector<uint32_t>> callees;
    std::map<uint32_t, std::vector<uint32_t>> taken;  // function -> every variable it reads, in declaration order
};

Reads reads(const Module& m) {
    Reads r;
    uint32_t function = 0;
    for (const Instruction& i : m.code) {
        const spv::Op op = i.opcode();
        if (op == spv::OpName) r.names[i.words[1]] = reinterpret_cast<const char*>(i.words.data() + 2);
        if (op == spv::OpEntryPoint) r.entries.insert(i.words[2]);
        if (op == spv::OpVariable && i.words[3] == spv::StorageClassUniformConstant) {
            r.variables.push_back(i.words[2]);
            r.pointerType[i.words[2]] = i.words[1];
        }
        if (op == spv::OpFunction) function = i.words[2];
        if (op == spv::OpFunctionCall) r.callees[function].push_back(i.words[3]);
        if (function && op != spv::OpFunctionCall)
            for (uint16_t at : i.ids)
                if (r.pointerType.count(i.words[at])) r.direct[function].insert(i.words[at]);
    }
    return r;
}

// What function `f` reads, itself or through its calls (SPIR-V has no recursion), in declaration order.
const std::vector<uint32_t>& taken(Reads& r, uint32_t f) {
    if (auto known = r.taken.find(f); known != r.taken.end()) return known->second;
    std::set<uint32_t> all = r.direct[f];
    for (uint32_t callee : r.callees[f])
        for (uint32_t v : taken(r, callee)) all.insert(v);
    std::vector<uint32_t> ordered;
    for (uint32_t v : r.variables)
        if (all.count(v)) ordered.push_back(v);
    return r.taken[f] = ordered;
}

// Each function given parameters -> its new type (OpTypeFunction: its own parameters, then the variables' pointers),
// an existing one where the module has it; the new ones in `added`.
std::map<uint32_t, uint32_t> functionTypes(Module& m, Reads& r, std::vector<Instruction>& added) {
    std::map<uint32_t, const Instruction*> types;
    for (const Instruction& i : m.code)
        if (i.opcode() == spv::OpTypeFunction) types[i.words[1]] = &i;
    std::map<uint32_t, uint32_t> out;
    for (const Instruction& i : m.code) {
        if (i.opcode() != spv::OpFunction || r.entries.count(i.words[2]) || taken(r, i.words[2]).empty()) continue;
        std::vector<uint32_t> operands(types.at(i.words[4])->words.begin() + 2, types.at(i.words[4])->words.end());
        for (uint32_t v : taken(r, i.words[2])) operands.push_back(r.pointerType[v]);
        const auto same = [&](const Instruction& t) {
            return t.opcode() == spv::OpTypeFunction && std::equal(t.words.begin() + 2, t.words.end(), operands.begin(), operands.end());
        };
        const auto inModule = std::find_if(m.code.begin(), m.code.end(), same);
        const auto inAdded = std::find_if(added.begin(), added.end(), same);
        if (inModule != m.code.end() || inAdded != added.end()) {
            out[i.words[2]] = (inModule != m.code.end() ? *inModule : *inAdded).words[1];
            continue;
        }
        out[i.words[2]] = m.header[3];
        operands.insert(operands.begin(), m.header[3]++);
        std::vector<uint16_t> ids;  // all but the result
        for (uint16_t k = 1; k < operands.size(); ++k) ids.push_back(k);
        added.push_back(instruction(spv::OpTypeFunction, operands, ids));
    }
    return out;
}

// flipRows' rewrite of one module: each read's new operands computed just before it (`code`), the constants they use
// (`constants`, put before the first function).
struct RowFlip {
    explicit RowFlip(Module& module) : m(module) {
        for (const Instruction& i : m.code)
            if (i.opcode() == spv::OpTypeVector) vectors[i.words[1]] = {i.words[2], i.words[3]};
    }

    // A sample at (s, -t), its gradients' t negated.
    void sample(Instruction& i) {
        const uint32_t mask = i.words.size() > 5 ? i.words[5] : 0;
        flipOperand(i, 4);
        if (mask & spv::ImageOperandsGradMask) {
            const size_t dx = 6 + !!(mask & spv::ImageOperandsBiasMask) + !!(mask & spv::ImageOperandsLodMask);
            flipOperand(i, dx);
            flipOperand(i, dx + 1);
        }
    }

    // A texel fetch of row y at row h - 1 - y, h the height of the level it reads.
    void fetch(Instruction& i) {
        const uint32_t coordinate = i.words[4], type = m.types.at(coordinate), component = vectors.at(type).first;
        const uint32_t mask = i.words.size() > 5 ? i.words[5] : 0;
        const uint32_t one = constant(component, 1u), lod = mask & spv::ImageOperandsLodMask ? i.words[6] : constant(component, 0u);
        const uint32_t size = m.header[3]++, h = m.header[3]++, y = m.header[3]++, last = m.header[3]++, row = m.header[3]++;
        code.push_back(instruction(spv::OpImageQuerySizeLod, {type, size, i.words[3], lod}, {0, 2, 3}));
        code.push_back(instruction(spv::OpCompositeExtract, {component, h, size, 1}, {0, 2}));
        code.push_back(instruction(spv::OpCompositeExtract, {component, y, coordinate, 1}, {0, 2}));
        code.push_back(instruction(spv::OpISub, {component, last, h, one}, {0, 2, 3}));
        code.push_back(instruction(spv::OpISub, {component, row, last, y}, {0, 2, 3}));
        i.words[4] = m.header[3]++;
        code.push_back(instruction(spv::OpCompositeInsert, {type, i.words[4], row, coordinate, 1}, {0, 2, 3}));
    }

    Module& m;
    std::vector<Instruction> constants, code;

private:
    // The scalar constant `bits` of `type`, declared once.
    uint32_t constant(uint32_t type, uint32_t bits) {
        const auto key = std::make_pair(type, bits);
        if (auto known = scalars.find(key); known != scalars.end()) return known->second;
        constants.push_back(instruction(spv::OpConstant, {type, scalars[key] = m.header[3]++, bits}, {0}));
        return scalars[key];
    }

    // The constant (1, -1, 1...) of a float vector type.
    uint32_t flipOf(uint32_t type) {
        if (auto known = flips.find(type); known != flips.end()) return known->second;
        const auto [component, size] = vectors.at(type);
        const uint32_t one = constant(component, std::bit_cast<uint32_t>(1.0f));
        const uint32_t minusOne = constant(component, std::bit_cast<uint32_t>(-1.0f));
        std::vector<uint32_t> operands = {type, flips[type] = m.header[3]++};
        std::vector<uint16_t> ids = {0};
        for (uint32_t k = 0; k < size; ++k) {
            ids.push_back(uint16_t(operands.size()));
            operands.push_back(k == 1 ? minusOne : one);  // t is component 1
        }
        constants.push_back(instruction(spv::OpConstantComposite, operands, ids));
        return flips[type];
    }

    // Operand `at` of `i` times the flip, computed just before `i`.
    void flipOperand(Instruction& i, size_t at) {
        const uint32_t type = m.types.at(i.words[at]), flipped = m.header[3]++;
        code.push_back(instruction(spv::OpFMul, {type, flipped, i.words[at], flipOf(type)}, {0, 2, 3}));
        i.words[at] = flipped;
    }

    std::map<uint32_t, std::pair<uint32_t, uint32_t>> vectors;  // vector type -> its component type and size
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> scalars;  // (type, bits) -> constant
    std::map<uint32_t, uint32_t> flips;                         // float vector type -> its flip constant
};

}  // namespace

TextureParameters texturesAsParameters(const std::vector<uint32_t>& words) {
    Module m = spirv::parse(words, "textures as parameters");
    Reads r = reads(m);
    std::vector<Instruction> addedTypes, names;
    const std::map<uint32_t, uint32_t> newType = functionTypes(m, r, addedTypes);
    TextureParameters result;
    std::vector<Instruction> code;
    std::map<uint32_t, uint32_t> parameter;  // in the current function: variable -> the parameter taking it
    uint32_t function = 0;
    bool parameters = false;  // in the current function's parameters
    for (Instruction& i : m.code) {
        const spv::Op op = i.opcode();
        if (op == spv::OpFunction) {
            function = i.words[2];
            parameter.clear();
            if (auto t = newType.find(function); t != newType.end()) i.words[4] = t->second;
            parameters = newType.count(function);
        } else if (parameters && op != spv::OpFunctionParameter) {
            std::string& name = r.names[function];
            std::vector<std::string>& listed = result.textures[name.substr(0, name.find('('))];
            for (uint32_t v : taken(r, function)) {
                parameter[v] = m.header[3]++;
                code.push_back(instruction(spv::OpFunctionParameter, {r.pointerType[v], parameter[v]}, {0}));
                std::vector<uint32_t> named = spirvString(r.names[v]);
                named.insert(named.begin(), parameter[v]);
                names.push_back(instruction(spv::OpName, named, {0}));
                listed.push_back(r.names[v]);
            }
            parameters = false;
        }
        i.replaceIds(parameter);
        if (op == spv::OpFunctionCall && !r.entries.count(i.words[3]))
            for (uint32_t v : taken(r, i.words[3])) appendId(i, parameter.count(v) ? parameter[v] : v);
        code.push_back(std::move(i));
    }
    auto lastName = std::find_if(code.rbegin(), code.rend(), [](const Instruction& i) { return i.opcode() == spv::OpName; });
    code.insert(lastName.base(), std::make_move_iterator(names.begin()), std::make_move_iterator(names.end()));
    spirv::insertBeforeFunctions(code, std::move(addedTypes));
    m.code = std::move(code);
    result.words = spirv::validWords(m, "textures as parameters");
    return result;
}

std::vector<uint32_t> flipRows(const std::vector<uint32_t>& words) {
    Module m = spirv::parse(words, "flip rows");
    RowFlip flip(m);
    const uint32_t kOffsets =
        uint32_t(spv::ImageOperandsConstOffsetMask) | spv::ImageOperandsOffsetMask | spv::ImageOperandsConstOffsetsMask;
    bool fetches = false;
    for (Instruction& i : m.code) {
        const spv::Op op = i.opcode();
        const uint32_t mask = i.words.size() > 5 ? i.words[5] : 0;
        const bool sample = op == spv::OpImageSampleImplicitLod || op == spv::OpImageSampleExplicitLod;
        if ((sample || op == spv::OpImageFetch) && (mask & kOffsets)) throw std::runtime_error("flip rows: a read with an offset");
        if (sample)
            flip.sample(i);
        else if (op == spv::OpImageFetch)
            fetches = true, flip.fetch(i);
        else if ((op >= spv::OpImageSampleDrefImplicitLod && op <= spv::OpImageRead) ||
                 (op >= spv::OpImageSparseSampleImplicitLod && op <= spv::OpImageSparseRead))
            throw std::runtime_error("flip rows: a texture read other than a sample or fetch (SPIR-V opcode " + std::to_string(op) + ")");
        flip.code.push_back(std::move(i));
    }
    spirv::insertBeforeFunctions(flip.code, std::move(flip.constants));
    // A fetch's flip asks the image's size (OpImageQuerySizeLod): a capability of its own.
    if (fetches && std::none_of(flip.code.begin(), flip.code.end(), [](const Instruction& i) {
            return i.opcode() == spv::OpCapability && i.words[1] == spv::CapabilityImageQuery;
        }))
        flip.code.insert(flip.code.begin(), instruction(spv::OpCapability, {spv::CapabilityImageQuery}, {}));
    m.code = std::move(flip.code);
    return spirv::validWords(m, "flip rows");
}

}  // namespace hexc
