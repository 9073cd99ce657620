-- Camera drivers (Modules/camera, libhrpcam) from LuaJIT: v4l2, dummy or sim, chosen in config.
--
--   local camera = require('camera')
--   local cam = assert(camera.open(Config.load('camera')))
--   local frame, err, code = cam:grab(0.5)   -- frame.yuyv, frame.width, frame.height, frame.seq, frame.time,
--                                             -- frame.head[0..1], frame.angle[0..1] (torso roll, pitch);
--                                             -- nil, message, code on timeout/loss
--   cam:stats()   --> { frames, captured, short_frames, lost, opens, open_failures, control_errors,
--                 --     connected, last_error }
--   cam:close()
-- The frame is a reused cdata: its pixels are valid until the next grab.
local ffi = require('ffi')
local native = require('native')

ffi.cdef [[
typedef struct cam_config {
  const char *driver; const char *device;
  int width, height; double fps; int nbuffers; double reopen_interval;
  int exposure; int gain; int white_balance; int brightness, contrast, saturation;
  uint32_t seed; int robot_id; int head_joint[2];
} cam_config;
typedef struct cam_frame {
  const uint8_t *yuyv; int32_t width, height; uint32_t seq; double time; double head[2]; double angle[2];
} cam_frame;
typedef struct cam_stats {
  uint32_t frames, captured, short_frames, lost, opens, open_failures, control_errors;
  int32_t connected; char last_error[256];
} cam_stats;
typedef struct cam_camera cam_camera;
void cam_config_default(cam_config *cfg);
int cam_open(const cam_config *cfg, cam_camera **out, char *err, size_t errlen);
int cam_grab(cam_camera *cam, cam_frame *frame, double timeout_s, char *err, size_t errlen);
void cam_get_stats(cam_camera *cam, cam_stats *out);
void cam_close(cam_camera *cam);
]]

local C = native.load('cam')

local M = {
  C = C,
  EARG = -1, ETIMEOUT = -2, ENODEV = -3, EFORMAT = -4, ESHM = -5, ENOMEM = -6,
  CTRL_UNSET = -1000000,
}

local errbuf = ffi.new('char[512]')

local Camera = {}
Camera.__index = Camera

local CONTROLS = { 'exposure', 'gain', 'white_balance', 'brightness', 'contrast', 'saturation' }

local function opt(cfg, key)
  return rawget(cfg, key)   -- config tables are strict: absent optional keys must not raise
end

-- Opens the camera described by cfg (a Config/<platform>/camera.lua table):
--   driver ('v4l2' | 'dummy' | 'sim'), width, height, fps, and optionally device, nbuffers,
--   reopen_interval, seed, robot_id (-1: no shm), head_joint {pan, tilt} (0-based),
--   controls = { exposure = ..., gain = ..., white_balance = ..., brightness, contrast, saturation }
--   (-1 for automatic exposure or white balance).
-- Returns the camera, or nil and a message.
function M.open(cfg)
  if type(cfg) ~= 'table' then error('camera.open: config table expected', 2) end
  local c = ffi.new('cam_config')
  C.cam_config_default(c)
  -- keep the strings alive as long as the config struct is used (cam_open copies them)
  local driver, device = opt(cfg, 'driver'), opt(cfg, 'device')
  if type(driver) ~= 'string' then error("camera.open: 'driver' must be a string", 2) end
  c.driver = driver
  if device then c.device = device end
  c.width = opt(cfg, 'width') or c.width
  c.height = opt(cfg, 'height') or c.height
  c.fps = opt(cfg, 'fps') or c.fps
  c.nbuffers = opt(cfg, 'nbuffers') or c.nbuffers
  c.reopen_interval = opt(cfg, 'reopen_interval') or c.reopen_interval
  c.seed = opt(cfg, 'seed') or c.seed
  c.robot_id = opt(cfg, 'robot_id') or c.robot_id
  local hj = opt(cfg, 'head_joint')
  if hj then c.head_joint[0], c.head_joint[1] = hj[1], hj[2] end
  local controls = opt(cfg, 'controls') or {}
  for _, name in ipairs(CONTROLS) do
    local v = rawget(controls, name)
    if v ~= nil then c[name] = v end
  end
  local out = ffi.new('cam_camera *[1]')
  local rc = C.cam_open(c, out, errbuf, 512)
  if rc < 0 then return nil, ffi.string(errbuf), rc end
  local self = setmetatable({
    handle = ffi.gc(out[0], C.cam_close),
    frame = ffi.new('cam_frame'),
    st = ffi.new('cam_stats'),
    driver = driver,
  }, Camera)
  return self
end

-- Waits up to timeout s for a new frame: the frame (reused cdata), or nil, message, code.
function Camera:grab(timeout)
  local rc = C.cam_grab(self.handle, self.frame, timeout or 1.0, errbuf, 512)
  if rc < 0 then return nil, ffi.string(errbuf), rc end
  return self.frame
end

function Camera:stats()
  local s = self.st
  C.cam_get_stats(self.handle, s)
  return {
    frames = s.frames, captured = s.captured, short_frames = s.short_frames, lost = s.lost,
    opens = s.opens, open_failures = s.open_failures, control_errors = s.control_errors,
    connected = s.connected ~= 0, last_error = ffi.string(s.last_error),
  }
end

function Camera:close()
  if self.handle ~= nil then
    C.cam_close(ffi.gc(self.handle, nil))
    self.handle = nil
  end
end

return M
