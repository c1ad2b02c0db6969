-- End to end with Neovim's own LSP client (Neovim 0.7: vim.lsp.start_client
-- and buf_attach_client): on a copy of examples/pick_and_place.rsp (and of
-- its stimuli file, which the server's run of it uses), checks diagnostics
-- as you type, the run's diagnostics, hover, go to definition, rename and
-- formatting through Neovim's API, applying the edits with Neovim's own
-- functions.
-- Run by ctest (test `editor_neovim`):
--   ROBOTSIM_BINARY=... ROBOTSIM_SOURCE_DIR=... WORK_DIR=... \
--     nvim --headless --clean -c "luafile tests/editor/nvim_lsp_test.lua"
-- Exits 0 when every check holds, 1 (cquit) otherwise.

local binary = assert(os.getenv('ROBOTSIM_BINARY'), 'ROBOTSIM_BINARY is not set')
local source = assert(os.getenv('ROBOTSIM_SOURCE_DIR'), 'ROBOTSIM_SOURCE_DIR is not set')
local work = assert(os.getenv('WORK_DIR'), 'WORK_DIR is not set')

local function fail(message)
  io.stderr:write('nvim_lsp_test: FAILED: ' .. message .. '\n')
  vim.cmd('cquit 1')
end

local function check(condition, message)
  if not condition then error(message, 2) end
end

local function find_line(buf, pattern)
  for i, line in ipairs(vim.api.nvim_buf_get_lines(buf, 0, -1, false)) do
    if line:find(pattern) then return i - 1 end
  end
  error('no line matches ' .. pattern)
end

local function run()
  vim.fn.mkdir(work, 'p')
  local file = work .. '/pick_and_place.rsp'
  assert(vim.loop.fs_copyfile(source .. '/examples/pick_and_place.rsp', file))
  assert(vim.loop.fs_copyfile(source .. '/examples/pick_and_place.stim', work .. '/pick_and_place.stim'))
  vim.cmd('edit ' .. vim.fn.fnameescape(file))
  local buf = vim.api.nvim_get_current_buf()

  local client_id = vim.lsp.start_client({
    name = 'robotsim',
    cmd = { binary, 'lsp', '--stdio' },
    root_dir = work,
    flags = { debounce_text_changes = 50 },
  })
  check(client_id, 'the client did not start')
  vim.lsp.buf_attach_client(buf, client_id)
  check(vim.wait(10000, function()
    local c = vim.lsp.get_client_by_id(client_id)
    return c ~= nil and c.initialized
  end, 20), 'the server did not initialize')
  local client = vim.lsp.get_client_by_id(client_id)
  local encoding = client.offset_encoding or 'utf-16'

  -- Diagnostics as you type: misspell HRDHOME, then put it back.
  local line = find_line(buf, '^        HRDHOME')
  vim.api.nvim_buf_set_text(buf, line, 8, line, 15, { 'HRDHOM' })
  check(vim.wait(10000, function() return #vim.diagnostic.get(buf) > 0 end, 20), 'no diagnostics after a typo')
  local d = vim.diagnostic.get(buf)[1]
  check(d.lnum == line and d.col == 8, ('diagnostic at %d:%d'):format(d.lnum, d.col))
  check(d.message:find("unknown instruction 'HRDHOM'", 1, true), 'message: ' .. d.message)
  vim.api.nvim_buf_set_text(buf, line, 8, line, 14, { 'HRDHOME' })
  check(vim.wait(10000, function() return #vim.diagnostic.get(buf) == 0 end, 20), 'diagnostics stay after the fix')

  -- The run's diagnostics as you type: wait for input 5, which the stimuli
  -- file never turns on: the run (robotsim check's, with the .stim beside
  -- the program) ends in a deadlock there. Then put it back.
  local wait = find_line(buf, '^        WAITFOR 2 ON')
  -- The server's warning (nothing turns input 5 on) comes with the compile,
  -- and gives way to the run's deadlock at the same line.
  vim.api.nvim_buf_set_text(buf, wait, 16, wait, 17, { '5' })
  local function deadlock()
    local all = vim.diagnostic.get(buf)
    if #all == 1 and all[1].message:find('deadlock', 1, true) then return all[1] end
    return nil
  end
  check(vim.wait(10000, function() return deadlock() ~= nil end, 20),
        'no run diagnostic for a deadlock: ' .. vim.inspect(vim.diagnostic.get(buf)))
  d = deadlock()
  check(d.lnum == wait and d.col == 8, ('run diagnostic at %d:%d'):format(d.lnum, d.col))
  check(d.message:find('deadlock: input 5 never turns ON', 1, true), 'run message: ' .. d.message)
  vim.api.nvim_buf_set_text(buf, wait, 16, wait, 17, { '2' })
  check(vim.wait(10000, function() return #vim.diagnostic.get(buf) == 0 end, 20), 'the deadlock stays after the fix')

  -- Hover on the input number of "WAITFOR 2 ON": what drives input 2 (the
  -- stimuli file's line 12, and its reactive rules on lines 13 and 14).
  local input = { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = wait, character = 16 } }
  local inputReplies = vim.lsp.buf_request_sync(buf, 'textDocument/hover', input, 10000)
  local inputHover = inputReplies and inputReplies[client_id] and inputReplies[client_id].result
  check(inputHover, 'no hover on an input')
  check(inputHover.contents.value:find('input 2: driven by\n- the stimuli file pick_and_place.stim (line 12)\n' ..
                                      '- a reactive rule in pick_and_place.stim (line 13: when output 3 turns ON, it turns OFF)',
                                      1, true), 'input hover: ' .. inputHover.contents.value)

  -- Hover on the point ABOVE_PICK in "MOVEP ABOVE_PICK".
  local movep = find_line(buf, 'MOVEP ABOVE_PICK')
  local position = { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = movep, character = 16 } }
  local replies = vim.lsp.buf_request_sync(buf, 'textDocument/hover', position, 10000)
  local hover = replies and replies[client_id] and replies[client_id].result
  check(hover, 'no hover')
  check(hover.contents.value:find('**point** `ABOVE_PICK`', 1, true), 'hover: ' .. vim.inspect(hover))
  check(hover.contents.value:find('E=400 D=-200 C=0 B=250 A=0', 1, true), 'hover values: ' .. hover.contents.value)
  check(hover.contents.value:find('Tool centre point of rhino-scara', 1, true), 'hover tcp: ' .. hover.contents.value)

  -- Go to definition: the point's row after POINTS.
  replies = vim.lsp.buf_request_sync(buf, 'textDocument/definition', position, 10000)
  local def = replies and replies[client_id] and replies[client_id].result
  check(def, 'no definition')
  local target = def.range and def or def[1]
  check(target.range.start.line == find_line(buf, '^ABOVE_PICK '), 'definition: ' .. vim.inspect(def))

  -- Rename the label "next" (at the start of its line) to "again".
  local label = find_line(buf, '^next:')
  local rename = { textDocument = position.textDocument, position = { line = label, character = 1 }, newName = 'again' }
  replies = vim.lsp.buf_request_sync(buf, 'textDocument/rename', rename, 10000)
  local edit = replies and replies[client_id] and replies[client_id].result
  check(edit, 'no rename edit')
  vim.lsp.util.apply_workspace_edit(edit, encoding)
  local lines = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
  check(lines[label + 1]:find('^again:   OUTSIG 1 ON'), 'renamed label: ' .. lines[label + 1])
  check(find_line(buf, 'JMPVAR PARTS < 3 again'), 'renamed jump')

  -- Formatting: the comment column goes to 36 (the example has it at 32).
  local params = { textDocument = position.textDocument, options = { tabSize = 8, insertSpaces = true } }
  replies = vim.lsp.buf_request_sync(buf, 'textDocument/formatting', params, 10000)
  local edits = replies and replies[client_id] and replies[client_id].result
  check(edits and #edits > 0, 'no formatting edits')
  vim.lsp.util.apply_text_edits(edits, buf, encoding)
  lines = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
  local set = find_line(buf, '^        SET PARTS 0')
  check(lines[set + 1] == '        SET PARTS 0' .. string.rep(' ', 17) .. '; nothing placed yet',
        'formatted: [' .. lines[set + 1] .. ']')
  check(lines[label + 1] == 'again:  OUTSIG 1 ON' .. string.rep(' ', 17) .. '; run the conveyor ...',
        'formatted label line: [' .. lines[label + 1] .. ']')
  -- Formatting again changes nothing.
  replies = vim.lsp.buf_request_sync(buf, 'textDocument/formatting', params, 10000)
  check(#replies[client_id].result == 0, 'formatting twice changed more')

  vim.lsp.stop_client(client_id)
  io.stderr:write('nvim_lsp_test: all checks passed\n')
  vim.cmd('qall!')
end

local ok, err = pcall(run)
if not ok then fail(tostring(err)) end
