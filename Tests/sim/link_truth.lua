-- Scenario of Tests/sim/link_truth_test.sh (./run_repl in lockstep, any body): Sim.link_truth
-- against Sim.truth, the standing robot's soles, and forward kinematics from the measured joint
-- angles (Lib/kinematics.lua's for the hands and the camera, the tests' URDF reader's for all).
-- Prints the figures and one line per check: "pass NAME" or "fail NAME".
-- luacheck: read globals Sim Body wait
local kin = require('kinematics')
local Config = require('Config')
local urdf_read = dofile(os.getenv('HRP_ROOT') .. '/Tests/kinematics/urdf_read.lua')

local function check(ok, name) print((ok and 'pass ' or 'fail ') .. name) end

-- R = Rz(yaw) Ry(pitch) Rx(roll), row-major {9}
local function rot(p) return urdf_read.rpy_rot(p.roll, p.pitch, p.yaw) end
local mul, matmul = urdf_read.apply, urdf_read.matmul
local function mulT(A, v)   -- A^T v
  return { A[1] * v[1] + A[4] * v[2] + A[7] * v[3], A[2] * v[1] + A[5] * v[2] + A[8] * v[3],
    A[3] * v[1] + A[6] * v[2] + A[9] * v[3] }
end
-- angle (rad) between two rotations
local function angle_between(A, B)
  local tr = 0
  for i = 0, 2 do for k = 0, 2 do tr = tr + A[3 * k + i + 1] * B[3 * k + i + 1] end end
  return math.acos(math.max(-1, math.min(1, (tr - 1) / 2)))
end
local function dist(a, b) return math.sqrt((a[1] - b[1]) ^ 2 + (a[2] - b[2]) ^ 2 + (a[3] - b[3]) ^ 2) end
local function finite(p)
  for _, k in ipairs({ 'x', 'y', 'z', 'roll', 'pitch', 'yaw' }) do
    local v = p[k]
    if type(v) ~= 'number' or v ~= v or v == math.huge or v == -math.huge then return false end
  end
  return true
end
local function xyz(p) return { p.x, p.y, p.z } end

local model = kin.load()
local body = model.name
local names = Sim.link_names()
local root = names[1]
print(string.format('body %s: %d links and frames, root %s: %s', body, #names, root, table.concat(names, ' ')))

assert(Sim.reset())
wait(1.0)

-- (a) the root link is the torso of Sim.truth
local t, r = Sim.truth(), Sim.link_truth(root)
local da = 0
for _, k in ipairs({ 'x', 'y', 'z', 'roll', 'pitch', 'yaw' }) do da = math.max(da, math.abs(t[k] - r[k])) end
print(string.format('root %s: x %.4f y %.4f z %.4f roll %.4f pitch %.4f yaw %.4f; '
  .. 'largest difference from Sim.truth %.3g', root, r.x, r.y, r.z, r.roll, r.pitch, r.yaw, da))
check(da < 1e-9 and not t.fallen, 'link_truth of the root link is Sim.truth (x y z roll pitch yaw)')

-- (b) standing: the soles on the carpet, mirror images about the torso
local Rt, pt = rot(r), xyz(r)
local ls, rs = Sim.link_truth('l_sole'), Sim.link_truth('r_sole')
local lt = mulT(Rt, { ls.x - pt[1], ls.y - pt[2], ls.z - pt[3] })
local rtor = mulT(Rt, { rs.x - pt[1], rs.y - pt[2], rs.z - pt[3] })
local dx, dy = math.abs(lt[1] - rtor[1]), math.abs(lt[2] + rtor[2])
print(string.format('soles: z l %.4f r %.4f m; torso frame l (%.4f, %.4f, %.4f) r (%.4f, %.4f, %.4f), '
  .. 'asymmetry x %.4f y %.4f m; tilt l %.4f r %.4f rad', ls.z, rs.z, lt[1], lt[2], lt[3], rtor[1], rtor[2], rtor[3],
  dx, dy, math.max(math.abs(ls.roll), math.abs(ls.pitch)), math.max(math.abs(rs.roll), math.abs(rs.pitch))))
check(math.abs(ls.z) < 0.004 and math.abs(rs.z) < 0.004,
  'the soles of the standing robot are on the carpet (|z| < 4 mm)')
check(dx < 0.002 and dy < 0.002 and math.abs(lt[3] - rtor[3]) < 0.002,
  'the soles are mirror images about the torso (within 2 mm)')

-- (c) forward kinematics from the measured angles: the right arm and the head moved off zero
local function off_zero(joint, v)
  local lo, hi = model:limits(joint)
  return math.max(lo + 0.05, math.min(hi - 0.05, v))
end
for k, i in ipairs(model.chain_index.rarm) do
  local j = model.joints[i]
  Body.set_command(j, off_zero(j, k % 2 == 1 and 0.4 or -0.4))
end
for _, i in ipairs(model.chain_index.head) do
  local j = model.joints[i]
  Body.set_command(j, off_zero(j, 0.3))
end
wait(1.5)
local q = Body.get_positions()
t = Sim.truth()
Rt, pt = rot(t), { t.x, t.y, t.z }
local function world(p) local w = mul(Rt, p) return { w[1] + pt[1], w[2] + pt[2], w[3] + pt[3] } end
local function arm_q(side)
  local qn = {}
  for k, i in ipairs(model.chain_index[side .. 'arm']) do qn[k] = q[i] end
  return qn
end
local chains = Config.load('robot').chains
local worst = 0
for _, side in ipairs({ 'r', 'l' }) do
  local tip = chains[side .. 'arm'].tip
  local fk = world(model:arm_fk(side, arm_q(side), nil, q))
  local lt2 = Sim.link_truth(tip)
  local e = dist(fk, xyz(lt2))
  worst = math.max(worst, e)
  print(string.format('%s: truth (%.4f, %.4f, %.4f) kinematics (%.4f, %.4f, %.4f) m: %.2f mm', tip, lt2.x, lt2.y,
    lt2.z, fk[1], fk[2], fk[3], e * 1e3))
end
local hq = {}
for k, i in ipairs(model.chain_index.head) do hq[k] = q[i] end
local cam = model:head_fk(hq, nil, q)
local cfk = world(cam)
local ct = Sim.link_truth(chains.head.tip)
local ce, ca = dist(cfk, xyz(ct)), angle_between(matmul(Rt, cam.R), rot(ct))
worst = math.max(worst, ce)
print(string.format('%s: truth (%.4f, %.4f, %.4f) kinematics (%.4f, %.4f, %.4f) m: %.2f mm, orientation %.2f mrad',
  chains.head.tip, ct.x, ct.y, ct.z, cfk[1], cfk[2], cfk[3], ce * 1e3, ca * 1e3))
print(string.format('hands and camera: largest error %.2f mm', worst * 1e3))
check(worst < 0.002 and ca < 0.005, 'the hands and the camera agree with the forward kinematics (2 mm, 5 mrad)')
-- every link and frame against the tests' own URDF reader's forward kinematics
local u = urdf_read.read(Config.robot_file(Config.load('robot').description, Config.robot()))
local fk = urdf_read.fk(u, function(joint) return q[model.index[joint] + 1] end)
local le, la, lworst = 0, 0, ''
for _, n in ipairs(names) do
  local lt3 = Sim.link_truth(n)
  local e, a = dist(world(fk[n].p), xyz(lt3)), angle_between(matmul(Rt, fk[n].R), rot(lt3))
  if e > le then le, lworst = e, n end
  la = math.max(la, a)
end
print(string.format('%d links and frames: largest error %.2f mm (%s), %.2f mrad', #names, le * 1e3, lworst, la * 1e3))
check(le < 0.002 and la < 0.005, 'every link and frame agrees with the URDF\'s forward kinematics (2 mm, 5 mrad)')

-- every link and frame comes back finite
local all_finite = true
for _, n in ipairs(names) do all_finite = all_finite and finite(Sim.link_truth(n)) end
check(all_finite, 'every link and frame of the body has a finite pose (' .. #names .. ')')

-- (d) bad names
local ok, err = pcall(Sim.link_truth, 'no_such_link')
print('unknown name: ' .. tostring(err))
check(not ok and tostring(err):find("'no_such_link'", 1, true) and tostring(err):find(root, 1, true),
  'an unknown name is an error naming it and some of the body\'s')
ok, err = pcall(Sim.link_truth, 42)
print('not a name: ' .. tostring(err))
check(not ok and tostring(err):find('link or frame', 1, true), 'a non-string name is an error')
ok, err = pcall(Sim.link_truth, root .. '\0x')
check(not ok and tostring(err):find('link or frame', 1, true), 'a name with a NUL byte is an error')
ok, err = pcall(Sim.link_truth, string.rep('a', 80))
check(not ok and tostring(err):find('longer than', 1, true), 'a name longer than the field is an error')
print('done')
