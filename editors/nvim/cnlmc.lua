-- cnlmc language server for Neovim's built-in LSP client.
-- Put this file on your runtimepath (e.g. ~/.config/nvim/lua/cnlmc.lua) and call
--   require("cnlmc").setup({ cmd = { "cnlmc", "lsp" } })
-- from init.lua. Needs Neovim >= 0.8 (vim.lsp.start); see docs/editors.md for 0.7.
local M = {}

function M.setup(opts)
  opts = opts or {}
  vim.filetype.add({ extension = { cnl = "cnl" } })
  vim.api.nvim_create_autocmd("FileType", {
    pattern = "cnl",
    callback = function(args)
      vim.bo[args.buf].commentstring = "# %s"
      vim.lsp.start({
        name = "cnlmc",
        cmd = opts.cmd or { "cnlmc", "lsp" },
        root_dir = vim.fs.dirname(vim.fs.find({ ".git", "pyproject.toml" }, { upward = true })[1])
          or vim.fn.getcwd(),
        init_options = { inlayHints = opts.inlay_hints ~= false, debounceMs = opts.debounce_ms or 120 },
      })
    end,
  })
end

return M
