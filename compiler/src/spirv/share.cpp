#include "spirv/share.h"

#include <map>
#include <set>

#include "spirv/module.h"

namespace hexc {
namespace {

using spirv::Instruction;

// A screen-space derivative, not an fwidth (a sum of two).
bool derivative(spv::Op op) {
    return op == spv::OpDPdx || op == spv::OpDPdy || op == spv::OpDPdxFine || op == spv::OpDPdyFine || op == spv::OpDPdxCoarse ||
           op == spv::OpDPdyCoarse;
}

// One function's blocks: each block's successors, and the block of each instruction.
struct Cfg {
    std::map<uint32_t, std::vector<uint32_t>> successors;
    uint32_t entry = 0;

    // Whether every path from the entry to `b` passes through `a`.
    bool dominates(uint32_t a, uint32_t b) const {
        if (a == b || a == entry) return true;
        std::set<uint32_t> seen{entry};
        std::vector<uint32_t> todo{entry};
        while (!todo.empty()) {
            const uint32_t at = todo.back();
            todo.pop_back();
            if (at == b) return false;
            if (auto it = successors.find(at); it != successors.end())
                for (uint32_t next : it->second)
                    if (next != a && seen.insert(next).second) todo.push_back(next);
        }
        return true;
    }
};

Cfg cfgOf(const std::vector<Instruction>& code, size_t begin, size_t end) {
    Cfg cfg;
    uint32_t block = 0;
    for (size_t k = begin; k < end; ++k) {
        const Instruction& i = code[k];
        const spv::Op op = i.opcode();
        if (op == spv::OpLabel) {
            block = i.words[1];
            if (!cfg.entry) cfg.entry = block;
            cfg.successors[block];
        } else if (op == spv::OpBranch) {
            cfg.successors[block] = {i.words[1]};
        } else if (op == spv::OpBranchConditional) {
            cfg.successors[block] = {i.words[2], i.words[3]};
        } else if (op == spv::OpSwitch) {
            cfg.successors[block] = {i.words[2]};  // the default, then (32-bit literal, label) pairs
            for (size_t w = 4; w < i.words.size(); w += 2) cfg.successors[block].push_back(i.words[w]);
        }
    }
    return cfg;
}

// The reads of one function [begin, end) merged: `replaced` maps each dropped result to the one it repeats.
void shareInFunction(std::vector<Instruction>& code, size_t begin, size_t end, std::map<uint32_t, uint32_t>& replaced,
                     std::vector<bool>& dropped) {
    const Cfg cfg = cfgOf(code, begin, end);
    std::map<uint32_t, std::vector<uint32_t>> sampledImage;                            // OpSampledImage result -> (image, sampler)
    std::map<uint32_t, uint32_t> imageOf;                                              // OpImage result -> the image
    std::map<std::vector<uint32_t>, std::vector<std::pair<uint32_t, uint32_t>>> seen;  // key -> (block, result)
    uint32_t block = 0;
    for (size_t k = begin; k < end; ++k) {
        Instruction& i = code[k];
        i.replaceIds(replaced);
        const spv::Op op = i.opcode();
        if (op == spv::OpLabel) block = i.words[1];
        if (op == spv::OpSampledImage) sampledImage[i.words[2]] = {i.words[3], i.words[4]};
        // textureSize (lod "shared") reads the image of a sampled image: the image it is.
        if (op == spv::OpImage && sampledImage.count(i.words[3])) imageOf[i.words[2]] = sampledImage.at(i.words[3]).front();
        if (op != spv::OpImageSampleExplicitLod && op != spv::OpImageQuerySizeLod && !derivative(op)) continue;
        std::vector<uint32_t> key = i.words;
        key[2] = 0;  // the result id
        // A sampled image made here is keyed by its image and sampler; one loaded whole (a template's combined sampler2D)
        // by its own id, which is then the same only for the same load.
        if (auto pair = sampledImage.find(i.words[3]); op == spv::OpImageSampleExplicitLod && pair != sampledImage.end()) {
            key[3] = 0;
            key.insert(key.end(), pair->second.begin(), pair->second.end());
        }
        if (op == spv::OpImageQuerySizeLod && imageOf.count(i.words[3])) key[3] = imageOf.at(i.words[3]);
        auto& earlier = seen[key];
        bool merged = false;
        for (const auto& [b, result] : earlier)
            if (cfg.dominates(b, block)) {
                replaced[i.words[2]] = result;
                dropped[k] = merged = true;
                break;
            }
        if (!merged) earlier.emplace_back(block, i.words[2]);
    }
}

}  // namespace

std::vector<uint32_t> shareTextureReads(const std::vector<uint32_t>& words) {
    spirv::Module m = spirv::parse(words, "shared texture reads");
    std::map<uint32_t, uint32_t> replaced;
    std::vector<bool> dropped(m.code.size());
    for (size_t k = 0; k < m.code.size(); ++k) {
        if (m.code[k].opcode() != spv::OpFunction) continue;
        size_t end = k;
        while (m.code[end].opcode() != spv::OpFunctionEnd) ++end;
        shareInFunction(m.code, k, end, replaced, dropped);
        k = end;
    }
    std::vector<Instruction> kept;
    for (size_t k = 0; k < m.code.size(); ++k) {
        if (dropped[k]) continue;
        m.code[k].replaceIds(replaced);  // uses before the definition they repeat (OpPhi of a loop)
        kept.push_back(std::move(m.code[k]));
    }
    m.code = std::move(kept);
    return m.words();
}

}  // namespace hexc
