"""cnlmc studio: a local web app over the engine (`cnlmc serve`): an editor served by the language
server's own functions, a live WebGL2 view, refinement with history, exports through the backend
registry, AR, behind a strict Content-Security-Policy and a per-session output folder.

The server (aiohttp) loads only when `serve` runs; docs/studio.md describes it."""
