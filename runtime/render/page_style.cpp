// The animation page's style sheet and body (see page.h).
#include "runtime/render/page.h"

namespace rs::render::page {

const std::string_view kStyle = R"CSS(
:root { --bg: #10121c; --panel: #181b27; --line: #2a2f40; --text: #c8ccd8; --dim: #7d8499;
        --accent: #ffff55; --in: #55ff55; --out: #ff5555; }
* { box-sizing: border-box; }
html, body { margin: 0; height: 100%; background: var(--bg); color: var(--text);
             font: 13px/1.35 ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, monospace; }
#app { display: grid; height: 100vh; grid-template-columns: 1fr 380px; grid-template-rows: 1fr auto; }
#view { position: relative; min-width: 0; min-height: 0; overflow: hidden; }
#cell { display: block; width: 100%; height: 100%; cursor: grab; touch-action: none; }
#cell.dragging { cursor: grabbing; }
#hint { position: absolute; right: 10px; bottom: 8px; color: var(--dim); pointer-events: none; }
#side { grid-row: 1 / span 2; grid-column: 2; background: var(--panel); border-left: 1px solid var(--line);
        display: flex; flex-direction: column; min-height: 0; }
#side h1 { font-size: 14px; margin: 10px 12px 4px; color: #fff; word-break: break-all; }
#side h2 { font-size: 11px; margin: 8px 12px 4px; color: var(--dim); text-transform: uppercase; letter-spacing: .08em; }
#listing { flex: 1 1 auto; min-height: 120px; overflow: auto; margin: 0 8px; padding: 0; list-style: none;
           background: var(--bg); border: 1px solid var(--line); }
#listing li { white-space: pre; padding: 0 6px 0 0; }
#listing li .n { display: inline-block; width: 4ch; margin-right: 1ch; text-align: right; color: var(--dim); }
#listing li.current { background: #3a3a10; color: var(--accent); }
#listing li.current .n { color: var(--accent); }
#motors { margin: 0 12px; border-collapse: collapse; width: calc(100% - 24px); }
#motors td { padding: 1px 4px; }
#motors td.m b { color: #fff; }
#motors td.m span { color: var(--dim); }
#motors td.v { text-align: right; color: #fff; width: 7ch; }
#motors td.r { width: 45%; }
#motors .bar { height: 6px; background: var(--line); position: relative; }
#motors .bar i { position: absolute; top: 0; bottom: 0; width: 2px; background: var(--accent); }
.lamps { display: flex; gap: 5px; margin: 0 12px; }
.lamp { width: 26px; height: 26px; border-radius: 50%; border: 1px solid var(--line); display: flex;
        align-items: center; justify-content: center; color: var(--dim); background: #0b0c12; }
#inputs .lamp.on { background: var(--in); color: #000; box-shadow: 0 0 8px var(--in); }
#outputs .lamp.on { background: var(--out); color: #000; box-shadow: 0 0 8px var(--out); }
#status { margin: 8px 12px 10px; color: var(--dim); min-height: 2.7em; white-space: pre-wrap; }
#status.failed { color: var(--out); }
#controls { grid-column: 1; display: flex; align-items: center; gap: 8px; padding: 6px 10px;
            background: var(--panel); border-top: 1px solid var(--line); }
#controls button, #controls select { background: #23283a; color: var(--text); border: 1px solid var(--line);
            border-radius: 3px; font: inherit; padding: 3px 9px; cursor: pointer; }
#controls button:hover { border-color: var(--dim); }
#play { min-width: 6ch; }
#timeline { flex: 1; min-width: 80px; accent-color: var(--accent); }
#time { min-width: 17ch; text-align: right; color: #fff; }
label { color: var(--dim); }
#app.with-chart { grid-template-rows: 1fr auto auto; }
#app.with-chart #side { grid-row: 1 / span 3; }
#chartPane { grid-column: 1; grid-row: 3; max-height: 40vh; overflow-y: auto; background: var(--bg);
             border-top: 1px solid var(--line); }
#chartWrap { position: relative; }
#chart { display: block; width: 100%; height: auto; cursor: pointer; }
#chartCursor { position: absolute; top: 0; bottom: 0; width: 2px; margin-left: -1px; background: var(--accent);
               pointer-events: none; opacity: .85; }
)CSS";

const std::string_view kBody = R"HTML(<div id="app" class="with-chart">
<div id="view"><canvas id="cell" aria-label="workcell"></canvas>
<div id="hint">drag: rotate &middot; wheel: zoom &middot; double-click: reset view &middot; space: play</div></div>
<aside id="side">
<h1 id="title"></h1>
<h2>Program</h2>
<ol id="listing"></ol>
<h2>Motors (encoder counts)</h2>
<table id="motors"></table>
<h2>Inputs</h2>
<div id="inputs" class="lamps"></div>
<h2>Outputs</h2>
<div id="outputs" class="lamps"></div>
<div id="status"></div>
</aside>
<div id="controls">
<button id="play" title="play / pause (space)">Play</button>
<button id="prev" title="previous instruction">&#9664;</button>
<button id="next" title="next instruction">&#9654;</button>
<input id="timeline" type="range" min="0" max="1" step="any" value="0" aria-label="time">
<span id="time"></span>
<label>speed <select id="speed">
<option value="0.1">0.1&times;</option><option value="0.25">0.25&times;</option>
<option value="0.5">0.5&times;</option><option value="1" selected>1&times;</option>
<option value="2">2&times;</option><option value="4">4&times;</option><option value="10">10&times;</option>
</select></label>
<label><input type="checkbox" id="axes"> axes</label>
<label title="the path of the tool centre point up to the time shown"><input type="checkbox" id="path" checked> path</label>
<button id="resetView" title="back to the starting view">reset view</button>
</div>
<div id="chartPane"><div id="chartWrap"><img id="chart" alt="the run over time: motors, tool centre point, gripper, inputs, outputs, source lines">
<div id="chartCursor"></div></div></div>
</div>
)HTML";

}  // namespace rs::render::page
