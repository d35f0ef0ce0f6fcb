// MaterialX's own ESSL (GLSL ES 3.00) for nodes of documents, from npm @needle-tools/materialx (MaterialX 1.39.4 in
// WebAssembly, pinned in tests/node's lock file): `node mx_generate.mjs` reads requests from stdin, one a line,
// ["DOC.mtlx", "NODE"], and answers each with one line of JSON, {"pixel", "vertex", "uniforms": [{"name", "type",
// "value"}]} (the uniforms with the values the document gives) or {"error"}. One process for every request: loading
// the WebAssembly module and the standard libraries takes about 2 s of processor time, a generation a tenth of that.
import { createRequire } from 'module';
import fs from 'fs';
import path from 'path';
import readline from 'readline';
import { fileURLToPath } from 'url';

const bin = path.join(path.dirname(fileURLToPath(import.meta.url)), '../node/node_modules/@needle-tools/materialx/bin');
// The Emscripten module is an ES module that reads its data file with CommonJS's require and __dirname under Node.
globalThis.require = createRequire(import.meta.url);
globalThis.__dirname = bin;
globalThis.__filename = path.join(bin, 'JsMaterialXGenShader.js');
const MaterialX = (await import(globalThis.__filename)).default;
// The package ships the data file as .data.txt.
const mx = await MaterialX({ locateFile: (p) => path.join(bin, p.endsWith('.data') ? p + '.txt' : p) });

const generator = mx.EsslShaderGenerator.create();
// One context for every document: it caches the node implementations it has generated, by name, which are the
// standard libraries' as long as no document defines nodes of its own (generate() refuses one that does).
const context = new mx.GenContext(generator);
const stdlib = mx.loadStandardLibraries(context);
context.getOptions().hwSrgbEncodeOutput = false;  // linear output, as hexc's

async function generate(docPath, nodeName) {
    const text = fs.readFileSync(docPath, 'utf8');
    const own = mx.createDocument();  // the document alone, without the libraries its node definitions would include
    await mx.readFromXmlString(own, text);
    if (own.getNodeDefs().length || own.getImplementations().length || own.getNodeGraphs().some((g) => g.getNodeDefString()))
        throw new Error(`${docPath} defines nodes of its own, which the shared context would keep for the next document`);
    const doc = mx.createDocument();
    doc.setDataLibrary(stdlib);
    await mx.readFromXmlString(doc, text);
    // NODE is a top-level node's name or GRAPH/OUTPUT, a nodegraph's output (whose interface inputs become uniforms).
    const [graphName, outputName] = nodeName.split('/');
    // A document whose output shares its name with a node (MaterialX names must be unique in a graph) keeps the node.
    const graph = outputName && doc.getNodeGraph(graphName);
    const node = graph ? graph.getOutput(outputName) || graph.getNode(outputName) : doc.getNode(nodeName);
    if (!node) throw new Error(`no ${nodeName} in ${docPath}`);
    const shader = generator.generate(nodeName.replace('/', '_'), node, context);
    const uniforms = [];
    const blocks = shader.getStage('pixel').getUniformBlocks();
    for (const [blockName, block] of Object.entries(blocks))
        for (let i = 0; i < block.size(); ++i) {
            const v = block.get(i);
            uniforms.push({ block: blockName, name: v.getVariable(), type: v.getType().getName(), value: v.getValue() ? v.getValue().getValueString() : null });
        }
    return { pixel: shader.getSourceCode('pixel'), vertex: shader.getSourceCode('vertex'), uniforms };
}

for await (const line of readline.createInterface({ input: process.stdin })) {
    let answer;
    try {
        answer = await generate(...JSON.parse(line));
    } catch (e) {
        answer = { error: String(e && e.stack || e) };
    }
    process.stdout.write(JSON.stringify(answer) + '\n');
}
