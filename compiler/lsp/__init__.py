"""The language server's helpers: thin adapters from compiler results to LSP values."""
