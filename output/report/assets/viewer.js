// sled report: the animation viewer. Reads the run's animation.glb (glTF 2.0 binary) that the
// page carries as base64, and draws its scene with WebGL: the node tree, the triangle and line
// meshes with their materials' base colours, and the translation, rotation and scale channels
// of its animation, played back at a chosen fraction of real time. It uses no library and no
// network. When it is ready (or fails) it says so on the page: `data-viewer` on <body> is
// `ready`, `error`, `no-webgl` or `absent`, which the report's browser test reads.
(function () {
  'use strict';

  var status = document.getElementById('viewer-status');

  function setState(state, text) {
    document.body.setAttribute('data-viewer', state);
    if (status) {
      status.setAttribute('data-state', state);
      status.textContent = text;
    }
  }

  // ---- reading the GLB ----------------------------------------------------------------------

  function decodeBase64(text) {
    var binary = atob(text.replace(/\s+/g, ''));
    var bytes = new Uint8Array(binary.length);
    for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }

  var GLB_MAGIC = 0x46546c67; // "glTF"
  var CHUNK_JSON = 0x4e4f534a;
  var CHUNK_BIN = 0x004e4942;

  function parseGlb(bytes) {
    var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    if (bytes.byteLength < 20 || view.getUint32(0, true) !== GLB_MAGIC) {
      throw new Error('the animation is not a glTF binary');
    }
    if (view.getUint32(4, true) !== 2) throw new Error('the animation is not glTF 2.0');
    var length = Math.min(view.getUint32(8, true), bytes.byteLength);
    var json = null;
    var bin = null;
    for (var offset = 12; offset + 8 <= length;) {
      var chunkLength = view.getUint32(offset, true);
      var type = view.getUint32(offset + 4, true);
      var data = bytes.subarray(offset + 8, offset + 8 + chunkLength);
      if (type === CHUNK_JSON) json = JSON.parse(new TextDecoder().decode(data));
      if (type === CHUNK_BIN) bin = data;
      offset += 8 + chunkLength;
    }
    if (!json) throw new Error('the glTF binary has no JSON chunk');
    return { json: json, bin: bin || new Uint8Array(0) };
  }

  var COMPONENTS = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT4: 16 };
  var ARRAY_TYPES = { 5120: Int8Array, 5121: Uint8Array, 5122: Int16Array, 5123: Uint16Array,
                      5125: Uint32Array, 5126: Float32Array };

  // An accessor's values as a tightly packed typed array (copied, so it is aligned).
  function readAccessor(gltf, index) {
    var accessor = gltf.json.accessors[index];
    var components = COMPONENTS[accessor.type];
    var Type = ARRAY_TYPES[accessor.componentType];
    if (!components || !Type) throw new Error('accessor ' + index + ' has an unknown type');
    var out = new Type(accessor.count * components);
    if (accessor.bufferView === undefined) return out;
    var view = gltf.json.bufferViews[accessor.bufferView];
    var start = gltf.bin.byteOffset + (view.byteOffset || 0) + (accessor.byteOffset || 0);
    var size = Type.BYTES_PER_ELEMENT;
    var stride = view.byteStride || components * size;
    if (start + stride * (accessor.count - 1) + components * size >
        gltf.bin.byteOffset + gltf.bin.byteLength) {
      throw new Error('accessor ' + index + ' reaches past the binary chunk');
    }
    var source = gltf.bin.buffer;
    if (stride === components * size) {
      return new Type(source.slice(start, start + accessor.count * components * size));
    }
    for (var i = 0; i < accessor.count; ++i) {
      var element = new Type(source.slice(start + i * stride, start + i * stride + components * size));
      out.set(element, i * components);
    }
    return out;
  }

  // ---- small matrix algebra (column-major 4x4, as WebGL wants) ------------------------------

  function identity() {
    var m = new Float32Array(16);
    m[0] = m[5] = m[10] = m[15] = 1;
    return m;
  }

  function multiply(a, b) {
    var out = new Float32Array(16);
    for (var col = 0; col < 4; ++col) {
      for (var row = 0; row < 4; ++row) {
        var sum = 0;
        for (var k = 0; k < 4; ++k) sum += a[k * 4 + row] * b[col * 4 + k];
        out[col * 4 + row] = sum;
      }
    }
    return out;
  }

  // Translation, rotation (unit quaternion x, y, z, w) and scale as one matrix.
  function composeTrs(t, q, s) {
    var x = q[0], y = q[1], z = q[2], w = q[3];
    var m = new Float32Array(16);
    m[0] = (1 - 2 * (y * y + z * z)) * s[0];
    m[1] = 2 * (x * y + z * w) * s[0];
    m[2] = 2 * (x * z - y * w) * s[0];
    m[4] = 2 * (x * y - z * w) * s[1];
    m[5] = (1 - 2 * (x * x + z * z)) * s[1];
    m[6] = 2 * (y * z + x * w) * s[1];
    m[8] = 2 * (x * z + y * w) * s[2];
    m[9] = 2 * (y * z - x * w) * s[2];
    m[10] = (1 - 2 * (x * x + y * y)) * s[2];
    m[12] = t[0];
    m[13] = t[1];
    m[14] = t[2];
    m[15] = 1;
    return m;
  }

  function perspective(fovY, aspect, near, far) {
    var f = 1 / Math.tan(fovY / 2);
    var m = new Float32Array(16);
    m[0] = f / aspect;
    m[5] = f;
    m[10] = (far + near) / (near - far);
    m[11] = -1;
    m[14] = (2 * far * near) / (near - far);
    return m;
  }

  function subtract(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function cross(a, b) {
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  }
  function normalize(v) {
    var length = Math.hypot(v[0], v[1], v[2]) || 1;
    return [v[0] / length, v[1] / length, v[2] / length];
  }

  function lookAt(eye, target, up) {
    var zAxis = normalize(subtract(eye, target));
    var xAxis = normalize(cross(up, zAxis));
    var yAxis = cross(zAxis, xAxis);
    var m = identity();
    for (var i = 0; i < 3; ++i) {
      m[i * 4] = xAxis[i];
      m[i * 4 + 1] = yAxis[i];
      m[i * 4 + 2] = zAxis[i];
    }
    m[12] = -(xAxis[0] * eye[0] + xAxis[1] * eye[1] + xAxis[2] * eye[2]);
    m[13] = -(yAxis[0] * eye[0] + yAxis[1] * eye[1] + yAxis[2] * eye[2]);
    m[14] = -(zAxis[0] * eye[0] + zAxis[1] * eye[1] + zAxis[2] * eye[2]);
    return m;
  }

  // The inverse transpose of the upper 3x3 block, for normals under non-uniform scale (the
  // ellipsoids are scaled spheres).
  function normalMatrix(m) {
    var a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], k = m[10];
    var det = a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
    var inv = det === 0 ? 0 : 1 / det;
    return new Float32Array([
      (e * k - f * h) * inv, (c * h - b * k) * inv, (b * f - c * e) * inv,
      (f * g - d * k) * inv, (a * k - c * g) * inv, (c * d - a * f) * inv,
      (d * h - e * g) * inv, (b * g - a * h) * inv, (a * e - b * d) * inv,
    ]);
  }

  function transformPoint(m, p) {
    return [m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
            m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
            m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]];
  }

  // ---- the animation ------------------------------------------------------------------------

  function readAnimation(gltf) {
    var channels = [];
    var duration = 0;
    var frames = 0;
    var animation = (gltf.json.animations || [])[0];
    if (!animation) return { channels: channels, duration: 0, frames: 0 };
    animation.channels.forEach(function (channel) {
      var sampler = animation.samplers[channel.sampler];
      if (channel.target.node === undefined) return;
      var times = readAccessor(gltf, sampler.input);
      var values = readAccessor(gltf, sampler.output);
      duration = Math.max(duration, times[times.length - 1] || 0);
      frames = Math.max(frames, times.length);
      channels.push({
        node: channel.target.node,
        path: channel.target.path,
        step: sampler.interpolation === 'STEP',
        times: times,
        values: values,
        size: channel.target.path === 'rotation' ? 4 : 3,
      });
    });
    return { channels: channels, duration: duration, frames: frames };
  }

  // The last key frame at or before t (binary search).
  function keyBefore(times, t) {
    var low = 0;
    var high = times.length - 1;
    if (t <= times[0]) return 0;
    if (t >= times[high]) return high;
    while (high - low > 1) {
      var middle = (low + high) >> 1;
      if (times[middle] <= t) low = middle; else high = middle;
    }
    return low;
  }

  function sampleChannel(channel, t) {
    var k = keyBefore(channel.times, t);
    var n = channel.size;
    var a = channel.values.subarray(k * n, k * n + n);
    if (channel.step || k + 1 >= channel.times.length) return Array.prototype.slice.call(a);
    var b = channel.values.subarray((k + 1) * n, (k + 2) * n);
    var span = channel.times[k + 1] - channel.times[k];
    var u = span > 0 ? Math.min(Math.max((t - channel.times[k]) / span, 0), 1) : 0;
    var out = [];
    var dot = 0;
    for (var i = 0; i < n; ++i) dot += a[i] * b[i];
    var sign = n === 4 && dot < 0 ? -1 : 1; // the short way round
    for (var j = 0; j < n; ++j) out.push(a[j] * (1 - u) + sign * b[j] * u);
    if (n === 4) {
      // Normalized linear interpolation: key frames at the output rate are close enough that it
      // is indistinguishable from slerp.
      var length = Math.hypot(out[0], out[1], out[2], out[3]) || 1;
      for (var q = 0; q < 4; ++q) out[q] /= length;
    }
    return out;
  }

  // ---- WebGL --------------------------------------------------------------------------------

  var VERTEX_SHADER = [
    'attribute vec3 position;',
    'attribute vec3 normal;',
    'uniform mat4 projection;',
    'uniform mat4 modelView;',
    'uniform mat3 normalTransform;',
    'varying vec3 viewNormal;',
    'void main() {',
    '  viewNormal = normalTransform * normal;',
    '  gl_Position = projection * modelView * vec4(position, 1.0);',
    '}',
  ].join('\n');

  var FRAGMENT_SHADER = [
    'precision mediump float;',
    'uniform vec4 color;',
    'uniform float lit;',
    'varying vec3 viewNormal;',
    'void main() {',
    '  vec3 n = normalize(viewNormal);',
    '  if (!gl_FrontFacing) n = -n;',
    '  float diffuse = max(dot(n, normalize(vec3(0.35, 0.6, 0.7))), 0.0);',
    '  float shade = mix(1.0, 0.38 + 0.62 * diffuse, lit);',
    '  gl_FragColor = vec4(color.rgb * shade, color.a);',
    '}',
  ].join('\n');

  function compile(gl, type, source) {
    var shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      throw new Error('shader: ' + gl.getShaderInfoLog(shader));
    }
    return shader;
  }

  function makeProgram(gl) {
    var program = gl.createProgram();
    gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, VERTEX_SHADER));
    gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, FRAGMENT_SHADER));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      throw new Error('program: ' + gl.getProgramInfoLog(program));
    }
    var uniforms = {};
    ['projection', 'modelView', 'normalTransform', 'color', 'lit'].forEach(function (name) {
      uniforms[name] = gl.getUniformLocation(program, name);
    });
    return {
      program: program,
      position: gl.getAttribLocation(program, 'position'),
      normal: gl.getAttribLocation(program, 'normal'),
      uniforms: uniforms,
    };
  }

  function buffer(gl, target, data) {
    var id = gl.createBuffer();
    gl.bindBuffer(target, id);
    gl.bufferData(target, data, gl.STATIC_DRAW);
    return id;
  }

  // The GPU side of each mesh: vertex buffers, indices, colour, draw mode, and the bounds of
  // its positions (for framing the camera).
  function uploadMeshes(gl, gltf, wide) {
    var materials = gltf.json.materials || [];
    return (gltf.json.meshes || []).map(function (mesh) {
      return mesh.primitives.map(function (primitive) {
        var positionIndex = primitive.attributes.POSITION;
        var positions = readAccessor(gltf, positionIndex);
        var part = {
          mode: primitive.mode === undefined ? 4 : primitive.mode,
          position: buffer(gl, gl.ARRAY_BUFFER, positions),
          normal: null,
          count: positions.length / 3,
          indices: null,
          indexType: 0,
          color: [0.7, 0.7, 0.7, 1],
          min: gltf.json.accessors[positionIndex].min,
          max: gltf.json.accessors[positionIndex].max,
        };
        if (primitive.attributes.NORMAL !== undefined) {
          part.normal = buffer(gl, gl.ARRAY_BUFFER, readAccessor(gltf, primitive.attributes.NORMAL));
        }
        if (primitive.indices !== undefined) {
          var indices = readAccessor(gltf, primitive.indices);
          if (indices instanceof Uint32Array && !wide) indices = new Uint16Array(indices);
          part.indices = buffer(gl, gl.ELEMENT_ARRAY_BUFFER, indices);
          part.indexType = indices instanceof Uint32Array ? gl.UNSIGNED_INT
                         : indices instanceof Uint16Array ? gl.UNSIGNED_SHORT : gl.UNSIGNED_BYTE;
          part.count = indices.length;
        }
        var material = materials[primitive.material];
        if (material && material.pbrMetallicRoughness &&
            material.pbrMetallicRoughness.baseColorFactor) {
          part.color = material.pbrMetallicRoughness.baseColorFactor;
        }
        return part;
      });
    });
  }

  // ---- the scene ----------------------------------------------------------------------------

  function Scene(gltf) {
    var json = gltf.json;
    this.nodes = (json.nodes || []).map(function (node) {
      return {
        mesh: node.mesh,
        children: node.children || [],
        matrix: node.matrix ? new Float32Array(node.matrix) : null,
        translation: node.translation || [0, 0, 0],
        rotation: node.rotation || [0, 0, 0, 1],
        scale: node.scale || [1, 1, 1],
        world: identity(),
      };
    });
    var scene = (json.scenes || [])[json.scene || 0];
    var isChild = {};
    this.nodes.forEach(function (node) {
      node.children.forEach(function (child) { isChild[child] = true; });
    });
    this.roots = scene ? scene.nodes
                       : this.nodes.map(function (_, i) { return i; }).filter(function (i) {
                         return !isChild[i];
                       });
    this.animation = readAnimation(gltf);
  }

  Scene.prototype.pose = function (t) {
    var nodes = this.nodes;
    this.animation.channels.forEach(function (channel) {
      var node = nodes[channel.node];
      if (node) node[channel.path] = sampleChannel(channel, t);
    });
    var visit = function (index, parent) {
      var node = nodes[index];
      var local = node.matrix || composeTrs(node.translation, node.rotation, node.scale);
      node.world = multiply(parent, local);
      node.children.forEach(function (child) { visit(child, node.world); });
    };
    this.roots.forEach(function (root) { visit(root, identity()); });
  };

  // The centre and radius of what the meshes cover in the current pose.
  Scene.prototype.bounds = function (meshes) {
    var low = [Infinity, Infinity, Infinity];
    var high = [-Infinity, -Infinity, -Infinity];
    this.nodes.forEach(function (node) {
      if (node.mesh === undefined) return;
      meshes[node.mesh].forEach(function (part) {
        if (!part.min || !part.max) return;
        for (var corner = 0; corner < 8; ++corner) {
          var p = transformPoint(node.world, [corner & 1 ? part.max[0] : part.min[0],
                                              corner & 2 ? part.max[1] : part.min[1],
                                              corner & 4 ? part.max[2] : part.min[2]]);
          for (var i = 0; i < 3; ++i) {
            low[i] = Math.min(low[i], p[i]);
            high[i] = Math.max(high[i], p[i]);
          }
        }
      });
    });
    if (!isFinite(low[0])) return { centre: [0, 0, 0], radius: 1 };
    var centre = [(low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2];
    var radius = Math.hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]) / 2;
    return { centre: centre, radius: radius || 1 };
  };

  // ---- the viewer ---------------------------------------------------------------------------

  function start() {
    var source = document.getElementById('animation-glb');
    if (!source) {
      setState('absent', status ? status.textContent : 'no animation');
      return;
    }
    var canvas = document.getElementById('viewer-canvas');
    var gl = canvas.getContext('webgl2', { antialias: true }) ||
             canvas.getContext('webgl', { antialias: true });
    if (!gl) {
      setState('no-webgl', 'This browser gives no WebGL, so the animation cannot be shown here; ' +
               'animation.glb in the run folder opens in Blender or any glTF viewer.');
      return;
    }
    var wide = typeof WebGL2RenderingContext !== 'undefined' && gl instanceof WebGL2RenderingContext;
    wide = wide || !!gl.getExtension('OES_element_index_uint');

    var gltf = parseGlb(decodeBase64(source.textContent));
    var scene = new Scene(gltf);
    var meshes = uploadMeshes(gl, gltf, wide);
    var program = makeProgram(gl);
    var duration = scene.animation.duration;

    var play = document.getElementById('viewer-play');
    var slider = document.getElementById('viewer-time');
    var clock = document.getElementById('viewer-clock');
    var speed = document.getElementById('viewer-speed');
    var reset = document.getElementById('viewer-reset');

    scene.pose(0);
    var home = scene.bounds(meshes);
    var camera = {};
    function resetCamera() {
      // From the occupant's right and a little in front and above: sled's -y is glTF's +z.
      camera.target = home.centre.slice();
      camera.distance = home.radius * 2.4;
      camera.azimuth = 0.55;
      camera.elevation = 0.3;
    }
    resetCamera();

    var time = 0;
    var playing = false;
    var last = 0;

    function draw() {
      var width = Math.max(1, Math.round(canvas.clientWidth * (window.devicePixelRatio || 1)));
      var height = Math.max(1, Math.round(canvas.clientHeight * (window.devicePixelRatio || 1)));
      if (canvas.width !== width || canvas.height !== height) {
        canvas.width = width;
        canvas.height = height;
      }
      scene.pose(time);
      gl.viewport(0, 0, canvas.width, canvas.height);
      gl.clearColor(0, 0, 0, 0);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      gl.enable(gl.DEPTH_TEST);
      gl.useProgram(program.program);
      var c = Math.cos(camera.elevation);
      var eye = [camera.target[0] + camera.distance * c * Math.sin(camera.azimuth),
                 camera.target[1] + camera.distance * Math.sin(camera.elevation),
                 camera.target[2] + camera.distance * c * Math.cos(camera.azimuth)];
      var view = lookAt(eye, camera.target, [0, 1, 0]);
      var near = Math.max(camera.distance / 200, 1e-4);
      gl.uniformMatrix4fv(program.uniforms.projection, false,
                          perspective(0.7, canvas.width / canvas.height, near, camera.distance * 20));
      scene.nodes.forEach(function (node) {
        if (node.mesh === undefined) return;
        var modelView = multiply(view, node.world);
        gl.uniformMatrix4fv(program.uniforms.modelView, false, modelView);
        gl.uniformMatrix3fv(program.uniforms.normalTransform, false, normalMatrix(modelView));
        meshes[node.mesh].forEach(function (part) {
          gl.bindBuffer(gl.ARRAY_BUFFER, part.position);
          gl.enableVertexAttribArray(program.position);
          gl.vertexAttribPointer(program.position, 3, gl.FLOAT, false, 0, 0);
          if (part.normal && program.normal >= 0) {
            gl.bindBuffer(gl.ARRAY_BUFFER, part.normal);
            gl.enableVertexAttribArray(program.normal);
            gl.vertexAttribPointer(program.normal, 3, gl.FLOAT, false, 0, 0);
          } else if (program.normal >= 0) {
            gl.disableVertexAttribArray(program.normal);
            gl.vertexAttrib3f(program.normal, 0, 0, 1);
          }
          gl.uniform4fv(program.uniforms.color, part.color);
          gl.uniform1f(program.uniforms.lit, part.normal ? 1 : 0);
          if (part.indices) {
            gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, part.indices);
            gl.drawElements(part.mode, part.count, part.indexType, 0);
          } else {
            gl.drawArrays(part.mode, 0, part.count);
          }
        });
      });
      clock.textContent = (time * 1000).toFixed(1) + ' ms';
      slider.value = duration > 0 ? String(Math.round((time / duration) * 1000)) : '0';
    }

    function tick(now) {
      if (!playing) return;
      if (last) time += ((now - last) / 1000) * Number(speed.value);
      last = now;
      if (time > duration) time = 0;
      draw();
      requestAnimationFrame(tick);
    }

    play.addEventListener('click', function () {
      playing = !playing;
      play.textContent = playing ? 'pause' : 'play';
      last = 0;
      if (playing) requestAnimationFrame(tick);
    });
    slider.addEventListener('input', function () {
      time = (Number(slider.value) / 1000) * duration;
      draw();
    });
    reset.addEventListener('click', function () {
      resetCamera();
      draw();
    });

    var drag = null;
    canvas.addEventListener('pointerdown', function (event) {
      drag = { x: event.clientX, y: event.clientY, pan: event.shiftKey };
      canvas.setPointerCapture(event.pointerId);
    });
    canvas.addEventListener('pointerup', function () { drag = null; });
    canvas.addEventListener('pointermove', function (event) {
      if (!drag) return;
      var dx = event.clientX - drag.x;
      var dy = event.clientY - drag.y;
      drag.x = event.clientX;
      drag.y = event.clientY;
      if (drag.pan) {
        // Move the target in the view plane, by the distance a pixel covers there.
        var perPixel = (camera.distance * 0.75) / canvas.clientHeight;
        var right = [Math.cos(camera.azimuth), 0, -Math.sin(camera.azimuth)];
        camera.target[0] -= right[0] * dx * perPixel;
        camera.target[2] -= right[2] * dx * perPixel;
        camera.target[1] += dy * perPixel;
      } else {
        camera.azimuth -= dx * 0.01;
        camera.elevation = Math.min(1.5, Math.max(-1.5, camera.elevation + dy * 0.01));
      }
      draw();
    });
    canvas.addEventListener('wheel', function (event) {
      event.preventDefault();
      camera.distance *= Math.exp(event.deltaY * 0.001);
      draw();
    }, { passive: false });

    draw();
    var glError = gl.getError();
    if (glError !== gl.NO_ERROR) throw new Error('WebGL error ' + glError + ' on the first frame');
    var meshCount = scene.nodes.filter(function (node) { return node.mesh !== undefined; }).length;
    setState('ready', scene.nodes.length + ' nodes (' + meshCount + ' drawn), ' +
             scene.animation.frames + ' key frames over ' + (duration * 1000).toFixed(1) + ' ms.');
    status.setAttribute('data-nodes', String(scene.nodes.length));
    status.setAttribute('data-frames', String(scene.animation.frames));
  }

  try {
    start();
  } catch (error) {
    setState('error', 'The viewer failed: ' + (error && error.message ? error.message : error));
  }
})();
