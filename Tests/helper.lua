-- Loaded by busted before every spec: makes the project's Lua modules findable.
local top = os.getenv('HRP_ROOT') or '.'
package.path = top .. '/Lib/?.lua;' .. top .. '/Player/?.lua;' .. top .. '/?.lua;' .. package.path
