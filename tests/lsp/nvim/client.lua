-- Headless Neovim as a real LSP client for cnlmc (run by tests/lsp/test_neovim.py).
-- Env: CNLMC_FILE (a .cnl file), CNLMC_OUT (JSON results), CNLMC_LSP_CMD (JSON list: the server command).
-- Works with Neovim 0.7 (vim.lsp.start_client) and newer (vim.lsp.start).
local file = os.getenv("CNLMC_FILE")
local out_path = os.getenv("CNLMC_OUT")
local cmd = vim.fn.json_decode(os.getenv("CNLMC_LSP_CMD"))
local results = { errors = {} }

local function finish()
  local f = io.open(out_path, "w")
  f:write(vim.fn.json_encode(results))
  f:close()
  vim.lsp.stop_client(vim.lsp.get_active_clients())
  vim.cmd("qa!")
end

local function diagnostics_of(bufnr)
  local out = {}
  for _, d in ipairs(vim.diagnostic.get(bufnr)) do
    table.insert(out, { lnum = d.lnum, col = d.col, end_col = d.end_col, code = d.code,
                        severity = d.severity, message = d.message })
  end
  return out
end

local function request(bufnr, method, params)
  local replies = vim.lsp.buf_request_sync(bufnr, method, params, 10000) or {}
  for _, reply in pairs(replies) do
    if reply.err then table.insert(results.errors, method .. ": " .. vim.inspect(reply.err)) end
    return reply.result
  end
end

local ok, err = pcall(function()
  vim.cmd("autocmd BufRead,BufNewFile *.cnl setfiletype cnl")
  vim.cmd("edit " .. vim.fn.fnameescape(file))
  local bufnr = vim.api.nvim_get_current_buf()
  results.filetype = vim.bo[bufnr].filetype
  local config = { name = "cnlmc", cmd = cmd, root_dir = vim.fn.fnamemodify(file, ":h"),
                   init_options = { debounceMs = 20 } }
  local client_id = vim.lsp.start_client(config)
  vim.lsp.buf_attach_client(bufnr, client_id)

  vim.wait(20000, function() return #vim.diagnostic.get(bufnr) > 0 end, 20)
  results.diagnostics = diagnostics_of(bufnr)

  local uri = vim.uri_from_bufnr(bufnr)
  local hover = request(bufnr, "textDocument/hover", { textDocument = { uri = uri }, position = { line = 0, character = 24 } })
  results.hover = hover and hover.contents and hover.contents.value or vim.NIL

  -- type a new line and ask for completion at its end
  local count = vim.api.nvim_buf_line_count(bufnr)
  vim.api.nvim_buf_set_lines(bufnr, count, count, false, { "lightly " })
  local completion = request(bufnr, "textDocument/completion",
    { textDocument = { uri = uri }, position = { line = count, character = 8 } })
  local items = completion and (completion.items or completion) or {}
  results.completion = {}
  for i, item in ipairs(items) do
    if i > 400 then break end
    table.insert(results.completion, { label = item.label, sortText = item.sortText })
  end

  -- fix the misspelling through the buffer: diagnostics must follow
  vim.api.nvim_buf_set_lines(bufnr, 1, 2, false, { "blue plastic" })
  vim.wait(20000, function()
    for _, d in ipairs(vim.diagnostic.get(bufnr)) do
      if d.code == "E001" then return false end
    end
    return true
  end, 20)
  results.diagnostics_after_edit = diagnostics_of(bufnr)
end)
if not ok then table.insert(results.errors, tostring(err)) end
finish()
