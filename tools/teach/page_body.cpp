// The teach page's body and its own style rules (on top of the animation
// page's style sheet, runtime/render/page_style.cpp, which it shares).
#include "tools/teach/page.h"

namespace rs::teach::page {

const std::string_view kStyle = R"CSS(
#side { overflow: auto; }
#fault { display: none; margin: 6px 12px; padding: 6px 8px; background: #3a0d0d; color: #ff5555;
         border: 1px solid #ff5555; font-weight: bold; white-space: pre-wrap; }
#fault.on { display: block; }
#motors tr.selected td, #axes tr.selected td { background: #2a2a10; }
#axesBox { display: none; }
#axesBox.on { display: block; }
#axes td.jog { white-space: nowrap; }
#axes td.help { color: var(--dim); font-size: 11px; }
#axes td.jog button { background: #23283a; color: var(--text); border: 1px solid var(--line); border-radius: 3px;
  font: inherit; padding: 1px 8px; cursor: pointer; }
body.cartesian #motors tr.selected td { background: none; }
#motors td.jog { white-space: nowrap; }
#motors td.jog button, .row button, #confirm button { background: #23283a; color: var(--text);
  border: 1px solid var(--line); border-radius: 3px; font: inherit; padding: 1px 8px; cursor: pointer; }
#motors td.jog button:hover, .row button:hover { border-color: var(--dim); }
.row button:disabled { opacity: .4; cursor: default; }
#motors td.range { color: var(--dim); font-size: 11px; white-space: nowrap; }
#motors input[type=range] { width: 100%; accent-color: var(--accent); }
.row { display: flex; gap: 6px; align-items: center; margin: 2px 12px; flex-wrap: wrap; }
.row input[type=text] { background: var(--bg); color: #fff; border: 1px solid var(--line); font: inherit;
  padding: 2px 5px; width: 14ch; }
#tcp { color: #fff; }
#approach { color: var(--dim); }
#inputs .lamp, #outputs .lamp { cursor: pointer; }
#points { list-style: none; margin: 0 8px; padding: 0; max-height: 180px; overflow: auto; background: var(--bg);
          border: 1px solid var(--line); min-height: 2.5em; }
#points li { white-space: pre; padding: 0 6px; cursor: pointer; }
#points li.selected { background: #3a3a10; color: var(--accent); }
#points li .v { color: var(--dim); }
#points li.selected .v { color: var(--accent); }
#confirm { display: none; margin: 4px 12px; padding: 5px 8px; border: 1px solid var(--accent); color: var(--accent); }
#confirm.on { display: block; }
#message.failed { color: var(--out); }
#keys { display: none; margin: 4px 12px; color: var(--dim); white-space: pre; font-size: 11px; }
#keys.on { display: block; }
#viewonly, #where { display: none; margin: 4px 12px; }
#viewonly { padding: 5px 8px; border: 1px solid var(--accent); color: var(--accent); }
#where { color: #fff; }
body.readonly #viewonly, body.readonly #where { display: block; }
body.readonly .pendant, body.readonly #motors td.jog, body.readonly #motors td.r { display: none; }
)CSS";

const std::string_view kBody = R"HTML(<div id="app">
<div id="view"><canvas id="cell" aria-label="workcell"></canvas>
<div id="hint">drag: rotate &middot; wheel: zoom &middot; double-click: reset view &middot; ?: keys</div></div>
<aside id="side">
<h1 id="title"></h1>
<div id="fault" role="alert"></div>
<div id="viewonly">Read-only: this page follows <b>robotsim debug</b> and shows the run where it stopped.
Jog and teach with robotsim teach.</div>
<div id="where"></div>
<h2>Motors (encoder counts)<span class="pendant"> &middot; jog <select id="mode" aria-label="jog mode">
<option value="joint" selected>joint</option><option value="world">world</option><option value="tool">tool</option></select>
step <select id="step" aria-label="jog step">
<option value="1">1</option><option value="10" selected>10</option><option value="100">100</option></select>
<span id="stepUnit">counts</span></span></h2>
<table id="motors"></table>
<div id="axesBox" class="pendant"><h2 id="axesTitle">World axes</h2><table id="axes"></table></div>
<h2>Gripper</h2>
<div class="row"><span class="pendant"><button id="open">open</button><button id="close">close</button></span> <span id="gripper"></span></div>
<h2>Tool centre point (world)</h2>
<div class="row"><span id="tcp"></span> <span id="approach"></span></div>
<h2>Inputs<span class="pendant"> (click to switch)</span></h2>
<div id="inputs" class="lamps"></div>
<h2>Outputs</h2>
<div id="outputs" class="lamps"></div>
<div class="row"><span id="devices"></span><span class="pendant"> <button id="runCell">run the cell 1 s</button></span></div>
<div class="pendant">
<h2>Points</h2>
<ol id="points"></ol>
<div class="row"><input id="teachName" type="text" placeholder="name" aria-label="point name">
<button id="teach">TEACH</button></div>
<div class="row"><button id="goto">go to</button><button id="reteach">re-teach</button>
<button id="delete">delete</button><input id="newName" type="text" placeholder="new name" aria-label="new name">
<button id="rename">rename</button></div>
<div id="confirm"><span id="question"></span> <button id="yes">yes</button> <button id="asPose">as a pose</button> <button id="asCounts">as counts</button> <button id="no">no</button></div>
<h2>Cell</h2>
<div class="row"><button id="reset">reset cell</button><button id="read">read position</button>
<button id="reload">reload file</button></div>
</div>
<div id="status"><span id="message"></span></div>
<div id="keys"></div>
</aside>
<div id="controls">
<label><input type="checkbox" id="axes"> axes</label>
<button id="resetView" title="back to the starting view">reset view</button>
<span id="file"></span>
</div>
</div>
)HTML";

}  // namespace rs::teach::page
