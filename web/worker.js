// The WebAssembly module in a worker: the page stays responsive while a
// scene runs, and a long BEM solve is stopped by ending the worker.
//
// Messages in:  {id, files: [{name, bytes: ArrayBuffer}], scene: string}
// Messages out: {type: "ready"} | {type: "progress", id, step, steps, iteration, residual}
//               | {type: "result", id, outcome, ms} (outcome: the module's JSON)
let wasm = null;
let module = null;
let current = null;
const encoder = new TextEncoder();
const decoder = new TextDecoder();

async function instantiate() {
  const imports = {
    env: {
      persson_now_ms: () => performance.now(),
      persson_progress: (step, steps, iteration, residual) =>
        postMessage({ type: "progress", id: current, step, steps, iteration, residual }),
    },
  };
  module = module || await WebAssembly.compileStreaming(fetch("persson.wasm"));
  // The zip reader's crate links getrandom's browser backend, whose imports
  // (wasm-bindgen's placeholders) reading never calls: a stub that says so.
  for (const { module: m, name, kind } of WebAssembly.Module.imports(module)) {
    if (kind !== "function" || (imports[m] && imports[m][name])) continue;
    imports[m] = imports[m] || {};
    imports[m][name] = () => { throw new Error(`${m}.${name} is not provided to this module`); };
  }
  wasm = (await WebAssembly.instantiate(module, imports)).exports;
}

function copyIn(bytes) {
  const ptr = wasm.persson_alloc(bytes.length);
  new Uint8Array(wasm.memory.buffer, ptr, bytes.length).set(bytes);
  return ptr;
}

function output(len) {
  const ptr = wasm.persson_output();
  return decoder.decode(new Uint8Array(wasm.memory.buffer, ptr, len));
}

function run(files, scene) {
  wasm.persson_unmount_all();
  for (const f of files) {
    const name = encoder.encode(f.name);
    const bytes = new Uint8Array(f.bytes);
    wasm.persson_mount(copyIn(name), name.length, copyIn(bytes), bytes.length);
  }
  const text = encoder.encode(scene);
  const len = wasm.persson_run(copyIn(text), text.length);
  return JSON.parse(output(len));
}

const ready = instantiate().then(() => postMessage({ type: "ready" }));

onmessage = async (event) => {
  await ready;
  const { id, files, scene } = event.data;
  current = id;
  const t0 = performance.now();
  let outcome;
  try {
    outcome = run(files, scene);
  } catch (e) {
    // A trap: a bug of ours, not the input's. Its message, then a fresh instance.
    let message = String(e);
    try {
      message = output(wasm.persson_panic()) || message;
    } catch (_) { /* the message is lost with the instance */ }
    outcome = { status: "error", error: `internal error (please report it): ${message}` };
    await instantiate();
  }
  postMessage({ type: "result", id, outcome, ms: performance.now() - t0 });
};
