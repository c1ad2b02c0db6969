-- Run by test_nvim_setup.sh inside Neovim started with docs/editors.md's
-- configuration and nothing else: opens NVIM_SETUP_FILE (a program whose
-- line 3 is the unknown instruction HRDHOM) and checks that the
-- configuration gave it the robotsim type, attached the robotsim server,
-- and that the server's diagnostic lands on that line and word.
-- Exits 0 when all holds, 1 (cquit) otherwise.
local file = assert(os.getenv('NVIM_SETUP_FILE'), 'NVIM_SETUP_FILE is not set')

local function fail(message)
  io.stderr:write('nvim_setup_check: FAILED: ' .. message .. '\n')
  vim.cmd('cquit 1')
end

local ok, err = pcall(function()
  vim.cmd('edit ' .. vim.fn.fnameescape(file))
  local buf = vim.api.nvim_get_current_buf()
  assert(vim.bo[buf].filetype == 'robotsim', "filetype is '" .. vim.bo[buf].filetype .. "', not robotsim")
  local attached = vim.wait(10000, function() return #vim.lsp.buf_get_clients(buf) > 0 end, 20)
  assert(attached, 'no language server attached to the buffer')
  local names = {}
  for _, c in pairs(vim.lsp.buf_get_clients(buf)) do table.insert(names, c.name) end
  assert(table.concat(names, ',') == 'robotsim', 'attached: ' .. table.concat(names, ','))
  local shown = vim.wait(15000, function() return #vim.diagnostic.get(buf) > 0 end, 20)
  assert(shown, 'no diagnostic shown for the typo')
  local d = vim.diagnostic.get(buf)[1]
  assert(d.lnum == 2 and d.col == 8, ('diagnostic at %d:%d, not 2:8'):format(d.lnum, d.col))
  assert(d.message:find("unknown instruction 'HRDHOM'", 1, true), 'message: ' .. d.message)
  -- A second file shares the one server.
  local second = vim.fn.fnamemodify(file, ':h') .. '/second.rsp'
  vim.fn.writefile({ '        HRDHOME', '        END' }, second)
  vim.cmd('edit ' .. vim.fn.fnameescape(second))
  local buf2 = vim.api.nvim_get_current_buf()
  assert(vim.wait(10000, function() return #vim.lsp.buf_get_clients(buf2) > 0 end, 20), 'second buffer not attached')
  assert(#vim.lsp.get_active_clients() == 1, #vim.lsp.get_active_clients() .. ' servers for two files')
end)
if not ok then fail(tostring(err)) end
vim.cmd('qall!')
