// The dlfl viewer (docs/viewer.md): WebGL 1 with no library, so that the page works offline, in any browser
// and in headless Chromium's software renderer. The data (the <script id="dlfl-data"> element) holds the
// steps M_0 ... M_N; each is drawn as flat-shaded triangles coloured by face size, with its edges on top.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const canvas = $("view");

  // ---- the data --------------------------------------------------------------------------------------------

  function bytesOf(base64) {
    const text = atob(base64);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return bytes;
  }

  let data = null;
  try {
    data = JSON.parse($("dlfl-data").textContent);
  } catch (e) {
    data = { title: "dlfl viewer (no data: write a page with dlfl view)", steps: [] };
  }
  const steps = data.steps;

  // The view's centre and size: the bounding box of every step together, so that the camera stays put when
  // the slider moves.
  const low = [Infinity, Infinity, Infinity], high = [-Infinity, -Infinity, -Infinity];
  for (const step of steps) {
    for (let k = 0; k < 3; ++k) {
      low[k] = Math.min(low[k], step.bbox[0][k]);
      high[k] = Math.max(high[k], step.bbox[1][k]);
    }
  }
  const centre = steps.length ? [0, 1, 2].map((k) => (low[k] + high[k]) / 2) : [0, 0, 0];
  const radius = steps.length
    ? Math.max(1e-9, Math.hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]) / 2) : 1;

  // ---- WebGL -----------------------------------------------------------------------------------------------

  const contextOptions = { antialias: true, preserveDrawingBuffer: true };
  const gl = canvas.getContext("webgl", contextOptions) || canvas.getContext("experimental-webgl", contextOptions);

  function program(vertexSource, fragmentSource) {
    const p = gl.createProgram();
    for (const [type, source] of [[gl.VERTEX_SHADER, vertexSource], [gl.FRAGMENT_SHADER, fragmentSource]]) {
      const s = gl.createShader(type);
      gl.shaderSource(s, source);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
      gl.attachShader(p, s);
    }
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    return p;
  }

  // Faces: flat shading from a light at the eye; back faces (the inside of an open mesh) a darker, warmer
  // tint of their colour.
  const faceProgram = gl && program(
    "attribute vec3 position; attribute vec3 normal; attribute vec3 color;\n" +
    "uniform mat4 transform; varying vec3 faceNormal; varying vec3 faceColor;\n" +
    "void main() { faceNormal = normal; faceColor = color; gl_Position = transform * vec4(position, 1.0); }",
    "precision mediump float;\n" +
    "uniform vec3 toEye; varying vec3 faceNormal; varying vec3 faceColor;\n" +
    "void main() {\n" +
    "  float light = abs(dot(normalize(faceNormal), toEye));\n" +
    "  vec3 lit = faceColor * (0.35 + 0.65 * light);\n" +
    "  gl_FragColor = vec4(gl_FrontFacing ? lit : mix(lit, vec3(0.45, 0.25, 0.2), 0.55), 1.0);\n" +
    "}");
  const edgeProgram = gl && program(
    "attribute vec3 position; uniform mat4 transform;\n" +
    "void main() { gl_Position = transform * vec4(position, 1.0); }",
    "precision mediump float; void main() { gl_FragColor = vec4(0.1, 0.1, 0.1, 1.0); }");

  function buffer(array) {
    const b = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, array, gl.STATIC_DRAW);
    return b;
  }

  // A step's arrays for drawArrays: three vertices per triangle, each with the triangle's normal and colour
  // (flat shading needs them per triangle, and unindexed drawing needs no 32-bit index extension).
  function upload(step) {
    const p = new Float32Array(bytesOf(step.positions).buffer);
    const t = new Uint32Array(bytesOf(step.triangles).buffer);
    const c = bytesOf(step.triangle_colors);
    const e = new Uint32Array(bytesOf(step.edges).buffer);
    const triangles = t.length / 3;
    const position = new Float32Array(9 * triangles), normal = new Float32Array(9 * triangles);
    const color = new Uint8Array(9 * triangles);
    for (let i = 0; i < triangles; ++i) {
      const a = 3 * t[3 * i], b = 3 * t[3 * i + 1], d = 3 * t[3 * i + 2];
      const ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
      const vx = p[d] - p[a], vy = p[d + 1] - p[a + 1], vz = p[d + 2] - p[a + 2];
      const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      for (let k = 0; k < 3; ++k) {
        const v = 3 * t[3 * i + k], o = 9 * i + 3 * k;
        position[o] = p[v]; position[o + 1] = p[v + 1]; position[o + 2] = p[v + 2];
        normal[o] = nx; normal[o + 1] = ny; normal[o + 2] = nz;
        color[o] = c[3 * i]; color[o + 1] = c[3 * i + 1]; color[o + 2] = c[3 * i + 2];
      }
    }
    const line = new Float32Array(3 * e.length);
    for (let i = 0; i < e.length; ++i) {
      line[3 * i] = p[3 * e[i]]; line[3 * i + 1] = p[3 * e[i] + 1]; line[3 * i + 2] = p[3 * e[i] + 2];
    }
    return {
      triangles, lines: e.length / 2,
      position: buffer(position), normal: buffer(normal), color: buffer(color), line: buffer(line),
    };
  }

  // Built steps, the one on show kept; others dropped once they hold too many triangles together.
  const built = new Map();
  function buffersOf(index) {
    if (!built.has(index)) {
      let held = 0;
      for (const b of built.values()) held += b.triangles;
      if (held > 4000000) {
        for (const b of built.values())
          for (const name of ["position", "normal", "color", "line"]) gl.deleteBuffer(b[name]);
        built.clear();
      }
      built.set(index, upload(steps[index]));
    }
    return built.get(index);
  }

  // ---- the camera --------------------------------------------------------------------------------------------

  // Orbit about `target`: the eye lies in direction (cos e sin a, sin e, cos e cos a) from it, so front (a = 0,
  // e = 0) looks down -z with y up. `scale` is half the height (or width, if smaller) of what the view shows
  // at the target; the perspective view's eye is as far as makes the same size there.
  const namedViews = {
    front: [0, 0], back: [180, 0], left: [-90, 0], right: [90, 0], top: [0, 90], bottom: [0, -90],
    iso: [45, 35.264389682754654],
  };
  const fieldOfView = 30 * Math.PI / 180;
  const camera = { azimuth: 45, elevation: 35.264389682754654, scale: 1, target: centre.slice(), ortho: false };

  function fit() {
    camera.scale = 1.1 * radius;
    camera.target = centre.slice();
  }

  function frame() {
    const a = camera.azimuth * Math.PI / 180, e = camera.elevation * Math.PI / 180;
    const toEye = [Math.cos(e) * Math.sin(a), Math.sin(e), Math.cos(e) * Math.cos(a)];
    const right = [Math.cos(a), 0, -Math.sin(a)];
    const up = [toEye[1] * right[2] - toEye[2] * right[1], toEye[2] * right[0] - toEye[0] * right[2],
      toEye[0] * right[1] - toEye[1] * right[0]];
    return { toEye, right, up };
  }

  // Column-major 4x4: projection times view.
  function transform(width, height) {
    const { toEye, right, up } = frame();
    const t = camera.target;
    const reach = radius + Math.hypot(t[0] - centre[0], t[1] - centre[1], t[2] - centre[2]);
    const aspect = width / height;
    const halfH = aspect >= 1 ? camera.scale : camera.scale / aspect, halfW = halfH * aspect;
    const distance = camera.ortho ? 2 * reach + 1e-6 : camera.scale / Math.tan(fieldOfView / 2);
    const eye = [0, 1, 2].map((k) => t[k] + distance * toEye[k]);
    const near = camera.ortho ? 1e-6 : Math.max(distance - reach, distance * 1e-3);
    const far = distance + reach;
    // view: rows right, up, toEye; translation -R * eye
    const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    const view = [right[0], up[0], toEye[0], 0, right[1], up[1], toEye[1], 0, right[2], up[2], toEye[2], 0,
      -dot(right, eye), -dot(up, eye), -dot(toEye, eye), 1];
    let proj;
    if (camera.ortho) {
      proj = [1 / halfW, 0, 0, 0, 0, 1 / halfH, 0, 0, 0, 0, -2 / (far - near), 0, 0, 0,
        -(far + near) / (far - near), 1];
    } else {
      const sx = distance / halfW, sy = distance / halfH;  // the target's plane spans [-1, 1]
      proj = [sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, -(far + near) / (far - near), -1, 0, 0,
        -2 * far * near / (far - near), 0];
    }
    const m = new Float32Array(16);
    for (let c = 0; c < 4; ++c)
      for (let r = 0; r < 4; ++r) {
        let s = 0;
        for (let k = 0; k < 4; ++k) s += proj[4 * k + r] * view[4 * c + k];
        m[4 * c + r] = s;
      }
    return { matrix: m, toEye };
  }

  // ---- drawing -----------------------------------------------------------------------------------------------

  // Edges follow the step shown (on below 200k faces, as in `dlfl render`) until the user chooses.
  let current = 0, showEdges = true, edgesChosen = false, pending = false;

  function attribute(prog, name, b, size, type, normalized) {
    const at = gl.getAttribLocation(prog, name);
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.enableVertexAttribArray(at);
    gl.vertexAttribPointer(at, size, type, normalized, 0, 0);
    return at;
  }

  function draw() {
    pending = false;
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(canvas.clientHeight * ratio));
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    gl.viewport(0, 0, width, height);
    gl.clearColor(0.957, 0.957, 0.949, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    if (!steps.length) return;
    const b = buffersOf(current);
    const { matrix, toEye } = transform(width, height);
    gl.enable(gl.DEPTH_TEST);
    // Faces pushed back a little, so that their edges win the depth test (no z-fighting).
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    gl.useProgram(faceProgram);
    gl.uniformMatrix4fv(gl.getUniformLocation(faceProgram, "transform"), false, matrix);
    gl.uniform3fv(gl.getUniformLocation(faceProgram, "toEye"), toEye);
    const used = [attribute(faceProgram, "position", b.position, 3, gl.FLOAT, false),
      attribute(faceProgram, "normal", b.normal, 3, gl.FLOAT, false),
      attribute(faceProgram, "color", b.color, 3, gl.UNSIGNED_BYTE, true)];
    gl.drawArrays(gl.TRIANGLES, 0, 3 * b.triangles);
    for (const at of used) gl.disableVertexAttribArray(at);
    if (showEdges && b.lines > 0) {
      // Off for the lines: SwiftShader (Chromium's software WebGL) offsets lines too, and then loses them.
      gl.disable(gl.POLYGON_OFFSET_FILL);
      gl.useProgram(edgeProgram);
      gl.uniformMatrix4fv(gl.getUniformLocation(edgeProgram, "transform"), false, matrix);
      const at = attribute(edgeProgram, "position", b.line, 3, gl.FLOAT, false);
      gl.drawArrays(gl.LINES, 0, 2 * b.lines);
      gl.disableVertexAttribArray(at);
    }
  }

  function redraw() {
    if (!gl || pending) return;
    pending = true;
    requestAnimationFrame(draw);
  }

  // ---- the controls ------------------------------------------------------------------------------------------

  const slider = $("step"), edges = $("edges"), ortho = $("ortho");

  function showStep(index) {
    current = Math.min(Math.max(0, index | 0), Math.max(0, steps.length - 1));
    const step = steps[current];
    if (!step) return;
    if (!edgesChosen) edges.checked = showEdges = step.faces < 200000;
    $("step-label").textContent = step.label;
    $("step-counts").textContent = step.counts;
    const legend = $("legend");
    legend.textContent = "";
    for (const [sides, count, color] of step.face_sizes) {
      const entry = document.createElement("span");
      entry.className = "entry";
      const swatch = document.createElement("span");
      swatch.className = "swatch";
      swatch.style.background = color;
      entry.append(swatch, sides + "-gons: " + count);
      legend.append(entry, " ");
    }
  }

  $("title").textContent = data.title;
  slider.max = String(Math.max(0, steps.length - 1));
  $("steps").style.display = steps.length > 1 ? "" : "none";
  slider.addEventListener("input", () => { showStep(Number(slider.value)); redraw(); });
  edges.addEventListener("change", () => {
    showEdges = edges.checked;
    edgesChosen = true;
    redraw();
  });
  ortho.addEventListener("change", () => { camera.ortho = ortho.checked; redraw(); });
  for (const name of Object.keys(namedViews)) {
    const button = document.createElement("button");
    button.textContent = name;
    button.addEventListener("click", () => {
      [camera.azimuth, camera.elevation] = namedViews[name];
      fit();
      redraw();
    });
    $("views").append(button, " ");
  }

  // The fragment fixes the view, for links and for tests: #view=front&ortho=1&step=2&edges=0&ui=0, or
  // az=..&el=.. in degrees, zoom=Z (a factor on the fitted size).
  function applyFragment() {
    const options = new URLSearchParams(location.hash.slice(1));
    fit();
    if (options.has("view") && namedViews[options.get("view")])
      [camera.azimuth, camera.elevation] = namedViews[options.get("view")];
    if (options.has("az")) camera.azimuth = Number(options.get("az")) || 0;
    if (options.has("el")) camera.elevation = Math.max(-90, Math.min(90, Number(options.get("el")) || 0));
    if (options.has("zoom")) camera.scale /= Number(options.get("zoom")) || 1;
    if (options.has("ortho")) camera.ortho = options.get("ortho") === "1";
    ortho.checked = camera.ortho;
    if (options.has("edges")) {
      edges.checked = showEdges = options.get("edges") === "1";
      edgesChosen = true;
    }
    $("panel").classList.toggle("hidden", options.get("ui") === "0");
    if (options.has("step")) {
      // Through the slider itself, as a user's move would go.
      slider.value = options.get("step");
      slider.dispatchEvent(new Event("input"));
    }
  }

  // Mouse: left drag orbits, shift or right drag pans, the wheel zooms. Touch: one finger orbits, two pan and
  // pinch.
  let drag = null;
  function pan(dx, dy) {
    const { right, up } = frame();
    const perPixel = 2 * camera.scale / Math.min(canvas.clientWidth, canvas.clientHeight);
    for (let k = 0; k < 3; ++k) camera.target[k] -= (dx * right[k] - dy * up[k]) * perPixel;
  }
  function orbit(dx, dy) {
    camera.azimuth -= dx * 0.4;
    camera.elevation = Math.max(-90, Math.min(90, camera.elevation + dy * 0.4));
  }
  function zoom(factor) {
    camera.scale = Math.min(1e3 * radius, Math.max(1e-4 * radius, camera.scale * factor));
  }
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  canvas.addEventListener("mousedown", (e) => {
    drag = { x: e.clientX, y: e.clientY, pan: e.button !== 0 || e.shiftKey };
  });
  window.addEventListener("mouseup", () => { drag = null; });
  window.addEventListener("mousemove", (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    if (drag.pan) pan(dx, dy);
    else orbit(dx, dy);
    redraw();
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    zoom(Math.exp(e.deltaY * (e.deltaMode === 1 ? 0.05 : 0.002)));
    redraw();
  }, { passive: false });
  canvas.addEventListener("dblclick", () => { fit(); redraw(); });
  let touches = null;
  function touchState(e) {
    const list = Array.from(e.touches).map((t) => [t.clientX, t.clientY]);
    const x = list.reduce((s, p) => s + p[0], 0) / list.length, y = list.reduce((s, p) => s + p[1], 0) / list.length;
    const spread = list.length > 1 ? Math.hypot(list[0][0] - list[1][0], list[0][1] - list[1][1]) : 0;
    return { count: list.length, x, y, spread };
  }
  canvas.addEventListener("touchstart", (e) => { e.preventDefault(); touches = touchState(e); }, { passive: false });
  canvas.addEventListener("touchend", (e) => { touches = e.touches.length ? touchState(e) : null; });
  canvas.addEventListener("touchmove", (e) => {
    e.preventDefault();
    const now = touchState(e);
    if (touches && touches.count === now.count) {
      if (now.count === 1) orbit(now.x - touches.x, now.y - touches.y);
      else {
        pan(now.x - touches.x, now.y - touches.y);
        if (touches.spread > 0 && now.spread > 0) zoom(touches.spread / now.spread);
      }
      redraw();
    }
    touches = now;
  }, { passive: false });
  window.addEventListener("resize", redraw);
  window.addEventListener("hashchange", () => { applyFragment(); redraw(); });

  showStep(0);
  applyFragment();
  if (!gl) {
    $("message").textContent = "This browser offers no WebGL: the mesh cannot be drawn.";
  } else {
    draw();  // at once, not on the next frame: a headless screenshot is taken when the page has loaded
  }
})();
