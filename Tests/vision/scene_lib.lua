-- What the seeded sim-scene scripts (sim_scenes.lua, goal_scenes.lua) share: a lockstep participant
-- of dcm_sim that holds the body in the sim's test stance (Tests/sim/stance.lua) with the head where
-- a scene points it, places things through the sim block's requests, and grabs a rendered frame once
-- the world has settled.
--   local world = require('Tests.vision.scene_lib').new()
--   world.robot, world.ccfg (configs), world.vp (the vision pipeline), world.cm (its camera model)
--   world.stance(pan, tilt); world.tick(); world.request(kind, a, b, c, d)
--   local frame, q = world.frame()   -- a frame exposed after settling, the joint positions with it
--   world.leave()                    -- the lockstep goes on without this participant
local shm = require('shm')
local Config = require('Config')
local camera = require('camera')
local kinematics = require('kinematics')
local lockstep = require('lockstep')
local pipeline = require('Vision.pipeline')
local project = require('Vision.project')
local stance = require('Tests.sim.stance')

local M = {}

function M.new()
  local robot = Config.load('robot')
  local vcfg, ccfg = Config.load('vision'), Config.load('camera')
  local cam = assert(camera.open({ driver = 'sim', width = ccfg.width, height = ccfg.height }))
  local sensor, act = shm.open('dcm.sensor'), shm.open('dcm.actuator')
  local sim, sync = shm.open('sim'), shm.open('sync')
  local nj = #robot.joints
  local pose = stance.pose()
  local participant = lockstep.join()
  local scene = { sensor = sensor, sim = sim, nj = nj, robot = robot, ccfg = ccfg,
    vp = assert(pipeline.new(vcfg, ccfg, assert(kinematics.load()))), cm = project.from_config(ccfg) }

  function scene.stance(pan, tilt)
    act:begin_write()
    for i, name in ipairs(robot.joints) do
      local q = pose[name] or 0
      if name == 'head_pan' then q = pan elseif name == 'head_tilt' then q = tilt end
      act.command[i - 1] = q; act.hardness[i - 1] = 1; act.torque_enable[i - 1] = 1
    end
    act:end_write()
  end

  function scene.tick()   -- finish the current tick and wait for the next
    local t = sync.tick[0]
    act.tick_ack[0] = sensor.tick[0]
    participant:done(t)
    while sync.tick[0] == t do shm.C.shm_futex_wait(sync.tick, t, 0.05) end
  end

  function scene.request(kind, a, b, c, d)
    sim.request[0] = kind
    sim.args[0], sim.args[1], sim.args[2], sim.args[3] = a or 0, b or 0, c or 0, d or 0
    local seq = sim.request_seq[0] + 1
    shm.C.shm_fetch_add_u32(sim.request_seq, 1)
    for _ = 1, 200 do
      if sim.done_seq[0] == seq then return end
      scene.tick()
    end
    error('sim request ' .. kind .. ' not applied')
  end

  local q = {}
  function scene.frame()
    local frame
    for _ = 1, 20 do
      scene.tick()
      frame = cam:grab(0)
      if frame then break end
    end
    assert(frame, 'no frame from the sim')
    for _ = 1, 3 do frame = cam:grab(0) or frame; scene.tick() end   -- a frame exposed after settling
    for i = 1, nj do q[i] = sensor.position[i - 1] end
    return frame, q
  end

  function scene.leave() participant:leave(); cam:close() end

  return scene
end

return M
