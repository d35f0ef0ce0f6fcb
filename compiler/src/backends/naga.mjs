// hexc's naga driver (compiler/src/backends/naga.cpp runs it with `node --input-type=module`): loads npm naga-wasm
// from the node_modules folder HEXC_NODE_PATH names, says whether it could, then translates each SPIR-V module it is
// sent to WGSL. Frames, both ways: a 4-byte little-endian length and the bytes. hexc sends a module's words; the
// driver answers with a status byte ("o" ok, "e" error) and the WGSL or naga's message.
import { join } from "node:path";
import { pathToFileURL } from "node:url";

function answer(ok, text) {
    const body = Buffer.from(text, "utf8");
    const head = Buffer.alloc(5);
    head.write(ok ? "o" : "e", 0);
    head.writeUInt32LE(body.length, 1);
    process.stdout.write(Buffer.concat([head, body]));
}

let naga;
const folder = process.env.HEXC_NODE_PATH || "";
try {
    naga = await import(pathToFileURL(join(folder, "naga-wasm", "dist", "node.js")).href);
    answer(true, "naga-wasm " + (naga.nagaVersion ?? ""));
} catch (e) {
    answer(false, "cannot load the npm package naga-wasm from HEXC_NODE_PATH (" + (folder || "unset") + "): " + e.message);
    process.exit(0);
}

function translate(bytes) {
    const module = naga.parseSpirv(new Uint8Array(bytes));
    try {
        const info = naga.validate(module);
        try {
            return naga.writeWgsl(module, info);
        } finally {
            info.free?.();
        }
    } finally {
        module.free?.();
    }
}

let pending = Buffer.alloc(0);
process.stdin.on("data", (chunk) => {
    pending = Buffer.concat([pending, chunk]);
    while (pending.length >= 4 && pending.length >= 4 + pending.readUInt32LE(0)) {
        const size = pending.readUInt32LE(0);
        const bytes = pending.subarray(4, 4 + size);
        pending = pending.subarray(4 + size);
        try {
            answer(true, translate(bytes));
        } catch (e) {
            answer(false, String(e.message ?? e));
        }
    }
});
