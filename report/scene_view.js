// The 3D view of report.html and of `luxgrid view` (docs/report.md, "The 3D view"): scene.glb, as
// embedded in the page, drawn with three.js, also embedded. Drag to turn, right-drag or
// shift-drag to move, the wheel to zoom; a click on a surface gives its value there. The page's
// address may choose the start: #view=top (from above, north up) or #view=home, and
// #show=rooms,surfaces,luminaires,solids (the layers shown; the check boxes follow), and
// #pick=X,Y clicks at a place (below).
// luxgrid's frame (+z up) is glTF's (x, z, -y): the scene's root node turns one into the other.
const box = document.getElementById('scene-3d');
const say = (text) => {
  box.querySelector('.scene-3d-info').textContent = text;
};
try {
  const three = document.getElementById('scene-3d-three').textContent;
  // The module as a blob: an embedded page has no other file to import it from.
  const url = URL.createObjectURL(new Blob([three], {type: 'text/javascript'}));
  const THREE = await import(url);
  start(THREE);
} catch (error) {
  say('The 3D view could not start: ' + error.message);
  box.dataset.state = 'failed';
}

function parseGlb(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (view.getUint32(0, true) !== 0x46546c67) throw new Error('not a glTF binary');
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  // The BIN chunk's data follows its 8-byte header; both chunks start at multiples of 4.
  const bin = bytes.byteOffset + 20 + jsonLength + 8;
  return {json, buffer: bytes.buffer, bin};
}

function accessor(glb, index) {
  const a = glb.json.accessors[index];
  const v = glb.json.bufferViews[a.bufferView];
  const n = a.count * (a.type === 'VEC3' ? 3 : 1);
  const at = glb.bin + (v.byteOffset || 0);
  return a.componentType === 5126 ? new Float32Array(glb.buffer, at, n)
                                  : new Uint32Array(glb.buffer, at, n);
}

function start(THREE) {
  const text = document.getElementById('scene-3d-glb').textContent.replace(/\s+/g, '');
  const raw = atob(text);
  const bytes = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; ++i) bytes[i] = raw.charCodeAt(i);
  const glb = parseGlb(bytes);
  const g = glb.json;

  const materials = (g.materials || []).map((m) => {
    const f = m.pbrMetallicRoughness.baseColorFactor;
    const options = {
      color: new THREE.Color().setRGB(f[0], f[1], f[2]),  // linear, as glTF gives it
      side: m.doubleSided ? THREE.DoubleSide : THREE.FrontSide,
      transparent: m.alphaMode === 'BLEND',
      opacity: f[3],
      depthWrite: m.alphaMode !== 'BLEND',
    };
    const unlit = m.extensions && m.extensions.KHR_materials_unlit;
    return unlit ? new THREE.MeshBasicMaterial(options) : new THREE.MeshLambertMaterial(options);
  });
  const meshes = (g.meshes || []).map((mesh) => mesh.primitives.map((p) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(accessor(glb, p.attributes.POSITION), 3));
    let material = p.material !== undefined ? materials[p.material] : new THREE.MeshLambertMaterial();
    if (p.attributes.COLOR_0 !== undefined) {
      geometry.setAttribute('color', new THREE.BufferAttribute(accessor(glb, p.attributes.COLOR_0), 3));
      material = material.clone();
      material.vertexColors = true;
    }
    geometry.setIndex(new THREE.BufferAttribute(accessor(glb, p.indices), 1));
    if (p.mode === 1 || p.mode === 2) {
      const c = material.color;
      return {geometry, material: new THREE.LineBasicMaterial({color: c}), mode: p.mode};
    }
    geometry.computeVertexNormals();
    return {geometry, material};
  }));

  // The node tree as three.js objects; each keeps its glTF name and extras, and the kind of the
  // project object it belongs to (room, luminaire, grid, ...) for the layers.
  const layerOf = {room: 'rooms', obstacle: 'rooms', opening: 'rooms', luminaire: 'luminaires',
                   photometric_solid: 'solids', grid: 'surfaces', points: 'surfaces',
                   observers: 'surfaces'};
  const layers = {rooms: [], surfaces: [], luminaires: [], solids: []};
  const pickable = [];
  function build(index, parentKind) {
    const n = g.nodes[index];
    const object = new THREE.Group();
    object.name = n.name;
    const extras = n.extras || {};
    const kind = extras.kind || parentKind;
    object.userData = {extras, kind};
    if (n.matrix) {
      object.matrix.fromArray(n.matrix);
      object.matrix.decompose(object.position, object.quaternion, object.scale);
    }
    if (n.translation) object.position.fromArray(n.translation);
    if (n.rotation) object.quaternion.fromArray(n.rotation);
    if (n.scale) object.scale.fromArray(n.scale);
    if (n.mesh !== undefined) {
      const holder = new THREE.Group();
      for (const p of meshes[n.mesh]) {
        // A grid drawn over the face it lies on (5 mm off it): pulled towards the eye in depth,
        // so that it wins over the face however far away it is seen.
        if (kind === 'grid') {
          p.material.polygonOffset = true;
          p.material.polygonOffsetFactor = -2;
          p.material.polygonOffsetUnits = -2;
        }
        // glTF's modes 1 and 2: lines (an unglazed opening's outline), else triangles.
        const mesh = p.mode === 1 ? new THREE.LineSegments(p.geometry, p.material)
                   : p.mode === 2 ? new THREE.LineLoop(p.geometry, p.material)
                                  : new THREE.Mesh(p.geometry, p.material);
        mesh.userData = {node: object};
        holder.add(mesh);
        if (mesh.isMesh) pickable.push(mesh);  // not lines: a ray picks them a metre away
      }
      object.add(holder);
      if (layers[layerOf[kind]]) layers[layerOf[kind]].push(holder);
    }
    for (const c of n.children || []) object.add(build(c, kind));
    return object;
  }
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f4f4);
  for (const r of g.scenes[g.scene || 0].nodes) scene.add(build(r, 'project'));
  scene.add(new THREE.AmbientLight(0xffffff, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  sun.position.set(-0.4, 1.0, 0.7);
  scene.add(sun);
  scene.updateMatrixWorld(true);

  // --- layers -------------------------------------------------------------------------------
  const hash = new URLSearchParams(location.hash.slice(1));
  // #view=...: the view alone, filling the window (a page of its own, for a screen or a test).
  if (hash.has('view')) {
    document.body.classList.add('scene-3d-alone');
    box.style.setProperty('--scene-3d-height', 'calc(100vh - 2em)');
  }
  const shown = hash.has('show') ? new Set(hash.get('show').split(','))
                                 : new Set((box.dataset.show || '').split(','));
  for (const input of box.querySelectorAll('input[data-layer]')) {
    const layer = input.dataset.layer;
    input.checked = shown.has(layer);
    if (!layers[layer].length) input.parentElement.classList.add('scene-3d-none');
    input.addEventListener('change', () => {
      setLayer(layer, input.checked);
      render();
    });
    setLayer(layer, input.checked);
  }
  function setLayer(layer, on) {
    for (const o of layers[layer]) o.visible = on;
  }

  // --- legend -------------------------------------------------------------------------------
  const scale = (g.scenes[g.scene || 0].extras || {}).colour_scale;
  const legend = box.querySelector('.scene-3d-legend');
  if (scale) {
    const stops = scale.srgb_at_sixteenths.map((c, k) => `rgb(${c[0]},${c[1]},${c[2]}) ${k * 6.25}%`);
    const bar = document.createElement('div');
    bar.className = 'scene-3d-bar';
    bar.style.background = `linear-gradient(to top, ${stops.join(', ')})`;
    legend.appendChild(bar);
    for (const t of scale.ticks_lx) {
      const label = document.createElement('span');
      label.textContent = `${+t.toFixed(2)}`;
      label.style.bottom = `${(100 * (t - scale.min_lx)) / (scale.max_lx - scale.min_lx)}%`;
      bar.appendChild(label);
    }
    const unit = document.createElement('div');
    unit.textContent = 'lx';
    legend.appendChild(unit);
  } else {
    legend.remove();
  }

  // --- camera and controls ------------------------------------------------------------------
  const canvas = box.querySelector('canvas');
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({canvas, antialias: true, preserveDrawingBuffer: true});
  } catch (error) {
    say('The 3D view needs WebGL, which this browser does not offer.');
    box.dataset.state = 'no-webgl';
    return;
  }
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000)  // near and far set to the scene below;
  // Fitted to everything but the solids (their size is a drawing choice).
  const fit = new THREE.Box3();
  scene.traverse((o) => {
    if (o.isMesh && o.parent && !layers.solids.includes(o.parent)) fit.expandByObject(o);
  });
  const centre = fit.isEmpty() ? new THREE.Vector3() : fit.getCenter(new THREE.Vector3());
  const size = fit.isEmpty() ? 5 : fit.getSize(new THREE.Vector3()).length();
  // Depth resolution for the scene's size: a grid 5 mm off its wall stays in front of it.
  camera.near = size / 2000;
  camera.far = size * 50;
  const target = new THREE.Vector3();
  const orbit = new THREE.Spherical();
  function home(view) {
    target.copy(centre);
    if (view === 'top') {
      // From above, luxgrid's +y (glTF's -z) up the screen.
      orbit.set(size * 1.25, 1e-4, 0);
    } else {
      // From the south-west and above: luxgrid's (-0.9, -1.3, 1.2) is glTF's (-0.9, 1.2, 1.3).
      orbit.setFromVector3(new THREE.Vector3(-0.9, 1.2, 1.3).normalize().multiplyScalar(size * 1.15));
    }
  }
  function render() {
    camera.position.setFromSpherical(orbit).add(target);
    camera.up.set(0, 1, 0);
    if (orbit.phi < 1e-3) camera.up.set(0, 0, -1);
    camera.lookAt(target);
    renderer.render(scene, camera);
  }
  function resize() {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    renderer.setSize(w, h, false);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    render();
  }
  home(hash.get('view') || 'home');
  new ResizeObserver(resize).observe(canvas);
  resize();

  let drag = null;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (e) => {
    drag = {x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey, moved: 0};
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    drag.moved += Math.abs(dx) + Math.abs(dy);
    if (drag.pan) {
      const k = (2 * orbit.radius * Math.tan((camera.fov * Math.PI) / 360)) / canvas.clientHeight;
      const right = new THREE.Vector3().setFromMatrixColumn(camera.matrix, 0);
      const up = new THREE.Vector3().setFromMatrixColumn(camera.matrix, 1);
      target.addScaledVector(right, -dx * k).addScaledVector(up, dy * k);
    } else {
      orbit.theta -= (dx * 2 * Math.PI) / canvas.clientWidth;
      orbit.phi = Math.min(Math.PI - 1e-3, Math.max(1e-3, orbit.phi - (dy * Math.PI) / canvas.clientHeight));
    }
    render();
  });
  canvas.addEventListener('pointerup', (e) => {
    if (drag && drag.moved < 4) pick(e);
    drag = null;
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    orbit.radius *= Math.pow(1.1, Math.sign(e.deltaY));
    render();
  }, {passive: false});
  box.querySelector('button[data-home]').addEventListener('click', () => {
    home('home');
    render();
  });
  // A printed page shows the view the page opens with.
  window.addEventListener('beforeprint', () => {
    home(hash.get('view') || 'home');
    render();
  });

  // --- the value at a point -----------------------------------------------------------------
  const fmt = (v) => v.toFixed(2);
  const luxgridXYZ = (p) => `x ${fmt(p.x)}, y ${fmt(-p.z)}, z ${fmt(p.y)} m`;
  const ray = new THREE.Raycaster();
  function pick(e) {
    const r = canvas.getBoundingClientRect();
    const at = new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
    ray.setFromCamera(at, camera);
    const shownAll = (o) => !o || (o.visible && shownAll(o.parent));
    const hits = ray.intersectObjects(pickable.filter((m) => shownAll(m)), false);
    for (const hit of hits) {
      const node = hit.object.userData.node;
      const x = node.userData.extras;
      if (node.userData.kind === 'grid' && x.E_lx) {
        // Linear between the triangle's three grid points.
        const tri = new THREE.Triangle();
        const pos = hit.object.geometry.attributes.position;
        const a = hit.face.a, b = hit.face.b, c = hit.face.c;
        tri.setFromAttributeAndIndices(pos, a, b, c);
        const local = hit.object.worldToLocal(hit.point.clone());
        const w = tri.getBarycoord(local, new THREE.Vector3());
        const lx = w.x * x.E_lx[a] + w.y * x.E_lx[b] + w.z * x.E_lx[c];
        say(`${node.name}: ${lx.toFixed(1)} lx at ${luxgridXYZ(hit.point)} (between its grid points)`);
        return;
      }
      if (x.E_lx !== undefined) {
        say(`${node.name}: ${x.E_lx.toFixed(1)} lx` + (x.UGR !== undefined ? `, UGR ${x.UGR.toFixed(1)}` : ''));
        return;
      }
      if (node.userData.kind === 'luminaire' && x.photometry !== undefined) {
        say(`${node.name}: ${x.photometry}` + (x.flux_lm !== undefined ? `, ${x.flux_lm.toFixed(0)} lm` : '') +
            `, at ${x.position_m.map(fmt).join(', ')} m`);
        return;
      }
      // Rooms, obstacles and glass are seen through to what lies behind them.
      if (['room', 'obstacle', 'opening'].includes(node.userData.kind)) continue;
    }
    say('Click a calculation surface for its value.');
  }
  // #pick=X,Y: a click at that place of the canvas (fractions of its width and height from the
  // top left) once drawn, as a test's way to click.
  if (hash.has('pick')) {
    const [fx, fy] = hash.get('pick').split(',').map(Number);
    const r = canvas.getBoundingClientRect();
    pick({clientX: r.left + fx * r.width, clientY: r.top + fy * r.height});
  }
  box.dataset.state = 'ready';
}
