// Parses and validates each WGSL file given with naga (npm naga-wasm from HEXC_NODE_PATH, as hexc's driver loads it):
// for WGSL hexc writes without an entry point (`hexc library --target wgsl`, `--functions --targets wgsl`), which
// must stand as a module of its own. Prints naga's message and exits 1 on the first file it refuses.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { pathToFileURL } from "node:url";

const naga = await import(pathToFileURL(join(process.env.HEXC_NODE_PATH || "", "naga-wasm", "dist", "node.js")).href);
for (const file of process.argv.slice(2)) {
    try {
        naga.validate(naga.parseWgsl(readFileSync(file, "utf8")));
    } catch (e) {
        console.error(`${file}: ${e.formatted ?? e.message ?? e}`);
        process.exit(1);
    }
}
