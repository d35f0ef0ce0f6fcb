// MaterialX's own ESSL (GLSL ES 3.00) for one node of a document, from npm @needle-tools/materialx (MaterialX 1.39.4 in
// WebAssembly, pinned in tests/node's lock file): node mx_generate.mjs DOC.mtlx NODE prints
// {"pixel", "vertex", "uniforms": [{"name", "type", "value"}]} as JSON, the uniforms with the values the document gives.
import { createRequire } from 'module';
import fs from 'fs';
import path from 'path';
import { fileURLToPath } from 'url';

const bin = path.join(path.dirname(fileURLToPath(import.meta.url)), '../node/node_modules/@needle-tools/materialx/bin');
// The Emscripten module is an ES module that reads its data file with CommonJS's require and __dirname under Node.
globalThis.require = createRequire(import.meta.url);
globalThis.__dirname = bin;
globalThis.__filename = path.join(bin, 'JsMaterialXGenShader.js');
const MaterialX = (await import(globalThis.__filename)).default;
// The package ships the data file as .data.txt.
const mx = await MaterialX({ locateFile: (p) => path.join(bin, p.endsWith('.data') ? p + '.txt' : p) });

const [docPath, nodeName] = process.argv.slice(2);
const generator = mx.EsslShaderGenerator.create();
const context = new mx.GenContext(generator);
const stdlib = mx.loadStandardLibraries(context);
context.getOptions().hwSrgbEncodeOutput = false;  // linear output, as hexc's
const doc = mx.createDocument();
doc.setDataLibrary(stdlib);
await mx.readFromXmlString(doc, fs.readFileSync(docPath, 'utf8'));
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
process.stdout.write(JSON.stringify({ pixel: shader.getSourceCode('pixel'), vertex: shader.getSourceCode('vertex'), uniforms }));
