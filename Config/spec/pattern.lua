-- What the walk pattern's values must be (Lib/Config.lua checks it on every load of the pattern
-- concern; the keys and their meaning: Config/common/pattern.lua).
local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

-- a number above lo (or at least lo when closed), or false where `false` means the walk's value
local function positive(closed, allow_false)
  return function(v)
    if allow_false and v == false then return true end
    if not finite(v) or v < 0 or (v == 0 and not closed) then
      return string.format('must be a number %s 0%s, got %s', closed and '>=' or '>',
        allow_false and " or false (the walk's)" or '', tostring(v))
    end
    return true
  end
end

return {
  steps = function(v)
    if not finite(v) or v < 1 or v % 1 ~= 0 then return 'must be an integer >= 1, got ' .. tostring(v) end
    return true
  end,
  stepLength = function(v)
    if not finite(v) then return 'must be a number (m), got ' .. tostring(v) end
    return true
  end,
  tStep = positive(false, true),
  stepHeight = positive(true, true),
  zc = positive(false, true),
  dt = positive(false, true),
  samples = function(v)
    if v == false then return true end
    if not finite(v) or v < 1 or v % 1 ~= 0 then
      return "must be an integer >= 1 or false (the walk's), got " .. tostring(v)
    end
    return true
  end,
  Qe = positive(false, true),
  R = positive(false, true),
  lead = positive(true, true),
  hold = positive(true),
  blend = positive(true),
}
