// One boolean of bench_exact through Manifold's WebAssembly build (npm package
// manifold-3d), as a whole process like `trimlab trim`: read OBJ files, build the
// manifolds, compute, write the result as OBJ. A benchmark-only peer; the app never
// needs it. Usage (node 18+, manifold-3d installed under MODULES):
//   node manifold_difference.mjs MODULES OUT.obj A.obj [B.obj]
// With B: A minus B. Without: A alone converted (Manifold refuses self-crossing input,
// it does not resolve it). Prints one line: "manifold volume V ms T triangles N" (T: the
// boolean and the conversions, reading and writing excluded), or "manifold refused
// REASON" and exits 3.
import { readFileSync, writeFileSync, renameSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [modules, output, ...inputs] = process.argv.slice(2);
const Module = await import(pathToFileURL(join(modules, 'node_modules', 'manifold-3d', 'manifold.js')).href);

function readObj(path) {
  const positions = [];
  const indices = [];
  for (const line of readFileSync(path, 'utf8').split('\n')) {
    if (line.startsWith('v ')) {
      const [, x, y, z] = line.trim().split(/\s+/);
      positions.push(+x, +y, +z);
    } else if (line.startsWith('f ')) {
      const corners = line.trim().split(/\s+/).slice(1).map((c) => parseInt(c, 10) - 1);
      for (let k = 1; k + 1 < corners.length; ++k) indices.push(corners[0], corners[k], corners[k + 1]);
    }
  }
  return { positions: Float32Array.from(positions), indices: Uint32Array.from(indices) };
}

function writeObj(path, mesh) {
  const lines = [];
  const p = mesh.vertProperties;
  const stride = mesh.numProp;
  for (let v = 0; v < p.length / stride; ++v) lines.push(`v ${p[v * stride]} ${p[v * stride + 1]} ${p[v * stride + 2]}`);
  const t = mesh.triVerts;
  for (let f = 0; f < t.length; f += 3) lines.push(`f ${t[f] + 1} ${t[f + 1] + 1} ${t[f + 2] + 1}`);
  writeFileSync(`${path}.tmp`, lines.join('\n') + '\n');
  renameSync(`${path}.tmp`, path);
}

const wasm = await Module.default();
wasm.setup();
const read = inputs.map(readObj);
const start = process.hrtime.bigint();
const solids = read.map(({ positions, indices }) => {
  const mesh = new wasm.Mesh({ numProp: 3, vertProperties: positions, triVerts: indices });
  mesh.merge();
  const solid = new wasm.Manifold(mesh);
  const status = solid.status();
  if (status !== 'NoError') {
    console.log(`manifold refused ${status}`);
    process.exit(3);
  }
  return solid;
});
const result = solids.length > 1 ? wasm.Manifold.difference(solids[0], solids[1]) : solids[0];
const mesh = result.getMesh();
const ms = Number(process.hrtime.bigint() - start) / 1e6;
writeObj(output, mesh);
console.log(`manifold volume ${result.volume()} ms ${ms.toFixed(1)} triangles ${mesh.triVerts.length / 3}`);
