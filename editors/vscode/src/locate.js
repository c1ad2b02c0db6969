// Finding the robotsim command. The robotsim.path setting, when it is a
// path, is taken as it is; a name (the default, robotsim) is looked up on
// PATH and then in the places robotsim's package and `cmake --install`
// put it, as VS Code started from a desktop launcher may have a shorter
// PATH than a terminal. When none holds it, the message says where it
// looked and which setting to change. No VS Code here: the tests run it.
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');

// The usual install places, after PATH: the Debian package's /usr/bin,
// `cmake --install`'s default prefix /usr/local, a per-user prefix
// ~/.local, and /opt/robotsim.
function installPlaces(home) {
  return ['/usr/local/bin', '/usr/bin', path.join(home, '.local', 'bin'), '/opt/robotsim/bin'];
}

function isExecutableFile(file) {
  try {
    if (!fs.statSync(file).isFile()) return false;
    fs.accessSync(file, fs.constants.X_OK);
    return true;
  } catch {
    return false;
  }
}

const settingHint = 'set "robotsim.path" (Settings > Extensions > ROBOTSIM) to the full path of the robotsim command';

// { path } of the command to run, or { error, looked } when there is none.
// `setting` is robotsim.path; a relative path is taken from `base` (the
// workspace folder); `env` gives PATH and `home` the user's folder.
// `places` are the install places (tests give their own folders).
function locateRobotsim(setting, { env = process.env, home = os.homedir(), base = process.cwd(),
  places = installPlaces(home) } = {}) {
  const wanted = (setting || '').trim() || 'robotsim';
  const expanded = wanted === '~' || wanted.startsWith('~/') ? path.join(home, wanted.slice(1)) : wanted;
  if (expanded.includes('/') || expanded.includes(path.sep)) {
    const file = path.resolve(base, expanded);
    if (isExecutableFile(file)) return { path: file };
    const what = fs.existsSync(file) ? 'is not an executable file' : 'does not exist';
    return { error: `ROBOTSIM: robotsim.path is ${wanted}, which ${what}: ${settingHint}, or clear it to look on PATH.`,
      looked: [file] };
  }
  const looked = [...(env.PATH || '').split(path.delimiter).filter((d) => d !== ''), ...places]
    .map((dir) => path.join(dir, expanded));
  for (const file of looked)
    if (isExecutableFile(file)) return { path: file };
  return {
    error: `ROBOTSIM: the ${expanded} command is not on PATH nor in ${places.join(', ')}: install robotsim, or ${settingHint}.`,
    looked,
  };
}

module.exports = { locateRobotsim, installPlaces };
