// Regenerates Assets/meshes/bunny.obj from the npm package `bunny` (Public Domain):
//   npm pack bunny@1.0.1 && tar xzf bunny-1.0.1.tgz && node bunny-to-obj.js package/index.js > bunny.obj
const bunny = require(require("path").resolve(process.argv[2]));
let s = "# Stanford bunny (low-resolution reconstruction), from the npm package bunny@1.0.1 (Public Domain).\n" +
        "# Converted by Assets/tools/bunny-to-obj.js; original scan: Stanford 3D Scanning Repository.\n";
for (const p of bunny.positions) s += `v ${p[0]} ${p[1]} ${p[2]}\n`;
for (const c of bunny.cells) s += `f ${c[0] + 1} ${c[1] + 1} ${c[2] + 1}\n`;
process.stdout.write(s);
