// The drawing code every page of robotsim shares (see page.h): the
// animation of a run and the live teach pendant embed this same script, so
// both draw with one camera formula (runtime/render/camera.h), one palette
// (the stills' colours, model.style) and one forward-kinematics path:
//
//   motor counts -> joint values (precision, coupling) -> D-H forward
//   kinematics -> each part's lines, stored in its own frame's coordinates,
//   through one 3x4 matrix per part (view · frame [· finger])
//   -> one canvas path and one stroke per EGA colour.
//
// robotsimDrawing(model, canvas) prepares a page's model (animation.h's
// cellDrawing: fit, camera, style, robots, objects) once and returns the
// functions a page draws with; the page says where the motors are and
// where the objects are (a run's grasp events, a pendant's state).
//
// A cell's devices: an object whose pose is GONE (a feeder's empty slot,
// a part a sink took) is neither drawn nor listed; each sensor of
// model.sensors (its lines in world coordinates) is drawn only while the
// page says it is ON (setSensor), in its colour (scene.h kSensorOnColor).
#include "runtime/render/page.h"

namespace rs::render::page {

const std::string_view kDrawScript = R"JS(function robotsimDrawing(model, canvas) {
  'use strict';
  const style = model.style;  // the stills' colours and marks (palette.h, scene.h, draw.h)
  const EGA = style.palette;

  // ---- Maths. An affine map is a Float64Array(12), column-major: the
  // images of the x, y and z axes, then of the origin (Eigen's layout).
  const RAD = Math.PI / 180;
  function affine() { const m = new Float64Array(12); m[0] = m[4] = m[8] = 1; return m; }
  function multiply(a, b, out) {  // out = a·b; out is neither a nor b
    for (let c = 0; c < 12; c += 3) {
      const x = b[c], y = b[c + 1], z = b[c + 2];
      out[c] = a[0] * x + a[3] * y + a[6] * z;
      out[c + 1] = a[1] * x + a[4] * y + a[7] * z;
      out[c + 2] = a[2] * x + a[5] * y + a[8] * z;
    }
    out[9] += a[9]; out[10] += a[10]; out[11] += a[11];
    return out;
  }
  // sin and cos of degrees, exact at multiples of 90 (as kinematics/trig.h).
  const SC = [0, 1];
  function sincos(deg) {
    const quarter = Math.round(deg / 90);
    const r = (deg - 90 * quarter) * RAD, s = Math.sin(r), c = Math.cos(r);
    switch (((quarter % 4) + 4) % 4) {
      case 0: SC[0] = s; SC[1] = c; break;
      case 1: SC[0] = c; SC[1] = -s; break;
      case 2: SC[0] = -s; SC[1] = -c; break;
      default: SC[0] = -c; SC[1] = s;
    }
    return SC;
  }
  // camera.h: pixel = diag(s, -s, s)·Rx·Ry·Rz·(p + window - center) + (W/2, H/2, 0).
  function viewMatrix(view, win, zoom, W, H, out) {
    const s = zoom * 0.45 * Math.min(W, H) / model.fit.radius;
    const [sx, cx] = sincos(view[0]);  // destructuring copies SC at once
    const [sy, cy] = sincos(view[1]);
    const [sz, cz] = sincos(view[2]);
    const Rx = [1, 0, 0, 0, cx, sx, 0, -sx, cx];  // column-major 3x3
    const Ry = [cy, 0, -sy, 0, 1, 0, sy, 0, cy];
    const Rz = [cz, sz, 0, -sz, cz, 0, 0, 0, 1];
    const m3 = (a, b) => {
      const o = new Array(9);
      for (let c = 0; c < 9; c += 3)
        for (let r = 0; r < 3; r++) o[c + r] = a[r] * b[c] + a[3 + r] * b[c + 1] + a[6 + r] * b[c + 2];
      return o;
    };
    const R = m3(Rx, m3(Ry, Rz));
    for (let c = 0; c < 9; c += 3) { out[c] = s * R[c]; out[c + 1] = -s * R[c + 1]; out[c + 2] = s * R[c + 2]; }
    const c0 = model.fit.center;
    const wx = win[0] - c0[0], wy = win[1] - c0[1], wz = win[2] - c0[2];
    out[9] = out[0] * wx + out[3] * wy + out[6] * wz + W / 2;
    out[10] = out[1] * wx + out[4] * wy + out[7] * wz + H / 2;
    out[11] = out[2] * wx + out[5] * wy + out[8] * wz;
    return out;
  }
  // A_i = Rz(θ)·Tz(d)·Tx(a)·Rx(α), with the joint variable q.
  function dhMatrix(j, q, out) {
    const [st, ct] = j.revolute ? [...sincos(q)] : [j.sinTheta, j.cosTheta];
    const d = j.revolute ? j.d : q;
    const sa = j.sinAlpha, ca = j.cosAlpha;
    out[0] = ct; out[1] = st; out[2] = 0;
    out[3] = -ca * st; out[4] = ca * ct; out[5] = sa;
    out[6] = sa * st; out[7] = -sa * ct; out[8] = ca;
    out[9] = j.a * ct; out[10] = j.a * st; out[11] = d;
  }
  // Right-handed rotation by deg about the line [px, py, pz, dx, dy, dz].
  function aboutLine(ax, deg, out) {
    const a = deg * RAD, c = Math.cos(a), s = Math.sin(a), t = 1 - c;
    const px = ax[0], py = ax[1], pz = ax[2], x = ax[3], y = ax[4], z = ax[5];
    out[0] = t * x * x + c; out[1] = t * x * y + s * z; out[2] = t * x * z - s * y;
    out[3] = t * x * y - s * z; out[4] = t * y * y + c; out[5] = t * y * z + s * x;
    out[6] = t * x * z + s * y; out[7] = t * y * z - s * x; out[8] = t * z * z + c;
    out[9] = px - (out[0] * px + out[3] * py + out[6] * pz);
    out[10] = py - (out[1] * px + out[4] * py + out[7] * pz);
    out[11] = pz - (out[2] * px + out[5] * py + out[8] * pz);
    return out;
  }

  // ---- The model, prepared once: typed arrays, lines grouped by colour.
  function preparePart(p) {
    p.pts = Float64Array.from(p.pts);
    p.count = p.colors.length;
    p.screen = new Float64Array(4 * p.count);
    const lists = [];
    for (let c = 0; c < 16; c++) lists.push([]);
    p.colors.forEach((c, k) => lists[c & 15].push(k));
    p.byColor = lists.map((l) => (l.length ? Int32Array.from(l) : null));
  }
  const allParts = [];
  for (const r of model.robots) {
    r.n = r.joints.length;
    for (const j of r.joints) {
      [j.sinAlpha, j.cosAlpha] = [...sincos(j.alpha)];
      [j.sinTheta, j.cosTheta] = [...sincos(j.theta)];
    }
    r.F = [Float64Array.from(r.base)];
    for (let i = 1; i <= r.n; i++) r.F.push(affine());
    r.q = new Float64Array(r.n);
    r.A = affine();
    r.T = affine();
    r.finger = affine();
    r.zero = new Int32Array(r.letters.length);
    for (const p of r.parts) { preparePart(p); allParts.push(p); }
  }
  for (const o of model.objects) { preparePart(o); allParts.push(o); o.off = !!o.parked; }
  const sensors = model.sensors || [];
  for (const s of sensors) { preparePart(s); allParts.push(s); s.off = true; }
  function setSensor(i, on) { if (sensors[i]) sensors[i].off = !on; }
  const GONE = 'gone';  // what objectPose answers for an object not in the cell

  for (const o of model.objects) {
    o.W = affine();  // its pose in the world, for a caller that composes one
    o.T = affine();  // view · pose
  }
  const carrier = model.robots.find((r) => r.program) || null;

  function poseRobot(r, enc) {
    const n = r.n, q = r.q;
    for (let k = 0; k < n; k++) {
      const j = r.joints[k];
      q[k] = j.home + j.precision * (enc[j.encoder] || 0);
    }
    for (let k = 0; k + 1 < n; k++) {
      const j = r.joints[k];
      if (j.coupling) q[k + 1] -= q[k] - j.home;
    }
    for (let i = 1; i <= n; i++) {
      dhMatrix(r.joints[i - 1], q[i - 1], r.A);
      multiply(r.F[i - 1], r.A, r.F[i]);
    }
  }
  function projectPart(T, p) {
    const a = T[0], b = T[1], d = T[3], e = T[4], g = T[6], h = T[7], tx = T[9], ty = T[10];
    const pts = p.pts, out = p.screen;
    for (let i = 0, j = 0, n = 2 * p.count; j < 2 * n; i += 3, j += 2) {
      const x = pts[i], y = pts[i + 1], z = pts[i + 2];
      out[j] = a * x + d * y + g * z + tx;
      out[j + 1] = b * x + e * y + h * z + ty;
    }
  }
  // Poses every robot for the motor counts `enc` (the robot that runs the
  // program; the others stay at home, or where their r.enc says) and fills every part's screen
  // coordinates for the view matrix V. objectPose(o) is the map from object
  // o's stored pts to the world now, or null while it is where the
  // workcell placed it.
  const tmp = affine();
  function projectAll(V, enc, objectPose) {
    for (const r of model.robots) {
      const e = r.program ? enc : r.enc || r.zero;  // r.enc: another robot of a cell run, posed by the page
      poseRobot(r, e);
      for (const p of r.parts) {
        multiply(V, r.F[p.frame], r.T);
        if (p.kind === 'finger2' || p.kind === 'finger3') {
          const g = r.gripper, phi = g.precision * (e[g.motor] || 0);
          aboutLine(p.kind === 'finger2' ? g.axis2 : g.axis3, phi, r.finger);
          projectPart(multiply(r.T, r.finger, tmp), p);
        } else {
          projectPart(r.T, p);
        }
      }
    }
    for (const o of model.objects) {
      const P = objectPose(o);
      o.off = P === GONE || (!P && !!o.parked);
      if (o.off) continue;
      projectPart(P ? multiply(V, P, o.T) : V, o);
    }
    for (const s of sensors) if (!s.off) projectPart(V, s);
  }
  function apply(T, x, y, z) {
    return [T[0] * x + T[3] * y + T[6] * z + T[9], T[1] * x + T[4] * y + T[7] * z + T[10]];
  }

  // ---- The camera: the model's starting camera, plus the program's
  // VIEW/WINDOW (st.view, st.window), plus the mouse (view.user).
  const ctx = canvas.getContext('2d', { alpha: false });
  const view = { user: { rx: 0, ry: 0, zoom: 1 }, W: 1, H: 1, hairline: 1 };
  function cameraFor(st, user) {
    const c = model.camera;
    return {
      view: [c.view[0] + st.view[0] + user.rx, c.view[1] + st.view[1] + user.ry, c.view[2] + st.view[2]],
      window: [c.window[0] + st.window[0], c.window[1] + st.window[1], c.window[2] + st.window[2]],
      zoom: c.zoom * user.zoom,
    };
  }

  // ---- Drawing.
  // A part marked hot (p.hot: the animation marks the parts of a
  // collision) is drawn whole in red, EGA 4.
  function strokeParts() {
    for (let c = 0; c < 16; c++) {
      let any = false;
      ctx.beginPath();
      for (const p of allParts) {
        if (p.off) continue;
        if (p.hot) {
          if (c !== 4) continue;
          const s = p.screen;
          for (let j = 0; j < 4 * p.count; j += 4) { ctx.moveTo(s[j], s[j + 1]); ctx.lineTo(s[j + 2], s[j + 3]); }
          any = true;
          continue;
        }
        const idx = p.byColor[c];
        if (!idx) continue;
        const s = p.screen;
        for (let n = 0; n < idx.length; n++) {
          const j = 4 * idx[n];
          ctx.moveTo(s[j], s[j + 1]);
          ctx.lineTo(s[j + 2], s[j + 3]);
        }
        any = true;
      }
      if (any) { ctx.strokeStyle = EGA[c]; ctx.stroke(); }
    }
  }
  function strokeAxesAndTools(V, axes) {
    const L = style.axisLength * model.fit.radius;
    for (const r of model.robots) {
      if (axes) {
        for (let k = 0; k < 3; k++) {
          ctx.beginPath();
          for (const F of r.F) {
            const o = apply(V, F[9], F[10], F[11]);
            const e = apply(V, F[9] + L * F[3 * k], F[10] + L * F[3 * k + 1], F[11] + L * F[3 * k + 2]);
            ctx.moveTo(o[0], o[1]); ctx.lineTo(e[0], e[1]);
          }
          ctx.strokeStyle = EGA[style.axisColors[k]]; ctx.stroke();
        }
      }
      if (r.tool) {
        const F = r.F[r.n], p = apply(V, F[9], F[10], F[11]), R = style.toolRadius;
        ctx.beginPath();
        ctx.arc(p[0], p[1], R, 0, 2 * Math.PI);
        ctx.moveTo(p[0] - 2 * R, p[1]); ctx.lineTo(p[0] + 2 * R, p[1]);
        ctx.moveTo(p[0], p[1] - 2 * R); ctx.lineTo(p[0], p[1] + 2 * R);
        ctx.lineWidth = style.toolLineWidth; ctx.strokeStyle = EGA[style.toolColor]; ctx.stroke();
        ctx.lineWidth = view.hairline;
      }
    }
  }
  // One frame: camera state st ({view, window}), motor counts enc, objects
  // through objectPose, the axes when asked, a label at the top left;
  // overlay(V, ctx), when given, draws over the parts and under the tool
  // marks (the animation's tool path).
  const V = affine();
  function draw(st, enc, objectPose, axes, label, overlay) {
    const cam = cameraFor(st, view.user);
    viewMatrix(cam.view, cam.window, cam.zoom, view.W, view.H, V);
    projectAll(V, enc, objectPose);
    ctx.fillStyle = style.background;
    ctx.fillRect(0, 0, view.W, view.H);
    // One device pixel: Skia then draws hairlines, ten times faster than
    // stroking 5,000 wider lines (docs/render.md).
    ctx.lineWidth = view.hairline;
    ctx.lineCap = 'butt';
    strokeParts();
    if (overlay) overlay(V, ctx);
    strokeAxesAndTools(V, axes);
    ctx.fillStyle = EGA[7];
    ctx.font = '13px ui-monospace, "DejaVu Sans Mono", monospace';
    ctx.fillText(label, 10, 20);
  }
  // The still's projection: the starting camera plus st's VIEW/WINDOW, no
  // mouse; lines in `robotsim render --dump-lines` order, then the tool
  // centre points.
  function projectStill(st, enc, objectPose, width, height) {
    const cam = cameraFor(st, { rx: 0, ry: 0, zoom: 1 });
    const M = viewMatrix(cam.view, cam.window, cam.zoom, width, height, affine());
    projectAll(M, enc, objectPose);
    const lines = [], tools = [];
    for (const r of model.robots) {
      for (const p of r.parts) for (let j = 0; j < 4 * p.count; j += 4) lines.push(Array.from(p.screen.slice(j, j + 4)));
      if (r.tool) { const F = r.F[r.n]; tools.push(apply(M, F[9], F[10], F[11])); }
    }
    for (const o of model.objects) {
      if (o.off) continue;
      for (let j = 0; j < 4 * o.count; j += 4) lines.push(Array.from(o.screen.slice(j, j + 4)));
    }
    for (const s of sensors) {
      if (s.off) continue;
      for (let j = 0; j < 4 * s.count; j += 4) lines.push(Array.from(s.screen.slice(j, j + 4)));
    }
    return { lines, tools };
  }

  // ---- The mouse: drag rotates, the wheel zooms, a double click goes back
  // to the starting view; the canvas follows its box's size.
  function resetView() { view.user = { rx: 0, ry: 0, zoom: 1 }; }
  function attachCamera(request) {
    let drag = null;
    canvas.addEventListener('pointerdown', (e) => {
      drag = { x: e.clientX, y: e.clientY };
      canvas.setPointerCapture(e.pointerId);
      canvas.classList.add('dragging');
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      view.user.ry += 0.5 * (e.clientX - drag.x);
      view.user.rx += 0.5 * (e.clientY - drag.y);
      drag = { x: e.clientX, y: e.clientY };
      request();
    });
    const endDrag = () => { drag = null; canvas.classList.remove('dragging'); };
    canvas.addEventListener('pointerup', endDrag);
    canvas.addEventListener('pointercancel', endDrag);
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      view.user.zoom = Math.max(0.05, Math.min(50, view.user.zoom * Math.exp(-0.0015 * e.deltaY)));
      request();
    }, { passive: false });
    canvas.addEventListener('dblclick', () => { resetView(); request(); });
    function resize() {
      const box = canvas.parentElement.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
      view.W = Math.max(1, box.width); view.H = Math.max(1, box.height);
      canvas.width = Math.round(view.W * dpr); canvas.height = Math.round(view.H * dpr);
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      view.hairline = 1 / dpr;
      request();
    }
    new ResizeObserver(resize).observe(canvas.parentElement);
    resize();
  }

  return { carrier, affine, multiply, viewMatrix, projectAll, apply, cameraFor, draw, projectStill, attachCamera,
           resetView, view, ctx, setSensor, GONE };
}
)JS";

}  // namespace rs::render::page
