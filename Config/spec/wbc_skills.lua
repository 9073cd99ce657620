-- What a whole-body skill's values must be (Lib/Config.lua checks it on every load of a concern
-- wbc_skills/<name>; the keys and their meaning: Lib/wbc_skill.lua, docs/whole-body.md "Skills").
-- Each state's tasks are checked as the wbc config's (Config/spec/wbc.lua); the frames, joints and
-- the tasks a rule waits for are checked against the body and the wbc config in Lib/wbc_skill.lua.
local wbc = require('Config.spec.wbc')

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end
local function name_ok(x) return type(x) == 'string' and #x <= 31 and x:match('^[%a_][%w_]*$') ~= nil end

local RULE_KEYS = { go = true, reached = true, after = true, times = true }

-- One rule of state `from`: go (a state), reached (task = error bound), after (s), times.
local function rule(r, states)
  if type(r) ~= 'table' then return 'must be a table { go, reached, after, times }' end
  for k in pairs(r) do
    if not RULE_KEYS[k] then return "is not a key of a rule (go, reached, after, times)", tostring(k) end
  end
  if type(r.go) ~= 'string' or states[r.go] == nil then
    return string.format("must name a state of `states`, got '%s'", tostring(r.go)), 'go'
  end
  if r.reached == nil and r.after == nil then return 'needs `reached` or `after` (or both)' end
  if r.reached ~= nil then
    if type(r.reached) ~= 'table' or next(r.reached) == nil then
      return 'must map task names to error bounds (m or rad)', 'reached'
    end
    for t, b in pairs(r.reached) do
      if not finite(b) or b <= 0 then return 'must be an error bound > 0 (m or rad)', 'reached.' .. tostring(t) end
    end
  end
  if r.after ~= nil and (not finite(r.after) or r.after <= 0) then return 'must be a number > 0 (s)', 'after' end
  if r.times ~= nil and (type(r.times) ~= 'number' or r.times < 1 or r.times % 1 ~= 0) then
    return 'must be an integer >= 1', 'times'
  end
  return true
end

local function states(v)
  if type(v) ~= 'table' or next(v) == nil then return 'must be a table of name = { tasks = ..., next = ... }' end
  for name, st in pairs(v) do
    if not name_ok(name) then return 'must be named by a word of up to 31 letters, digits and _', tostring(name) end
    if type(st) ~= 'table' then return 'must be a table { tasks, next }', name end
    for k in pairs(st) do
      if k ~= 'tasks' and k ~= 'next' then
        return 'is not a key of a state (tasks, next)', name .. '.' .. tostring(k)
      end
    end
    if st.tasks ~= nil then
      local ok, sub = wbc.tasks(st.tasks)
      if ok ~= true then return ok, name .. '.tasks' .. (sub and '.' .. sub or '') end
      for t in pairs(st.tasks) do
        if not name_ok(t) then
          return 'must be a task name of up to 31 letters, digits and _', name .. '.tasks.' .. tostring(t)
        end
      end
    end
    local nx = st.next
    if nx ~= nil then
      if type(nx) ~= 'table' then return 'must be a rule or a list of rules', name .. '.next' end
      local list = nx.go ~= nil and { nx } or nx
      for i, r in ipairs(list) do
        local ok, sub = rule(r, v)
        if ok ~= true then
          return ok, name .. '.next' .. (nx.go ~= nil and '' or '.' .. i) .. (sub and '.' .. sub or '')
        end
      end
      if nx.go == nil and #list == 0 then return 'must be a rule or a list of rules', name .. '.next' end
    end
  end
  return true
end

local function initial(v, cfg)
  if type(v) ~= 'string' or type(cfg.states) ~= 'table' or cfg.states[v] == nil then
    return string.format("must name a state of `states`, got '%s'", tostring(v))
  end
  return true
end

return { initial = initial, states = states }
