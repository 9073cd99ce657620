-- Initial: stand still, head straight ahead; localize afresh when the game starts (GameFSM.standstill).
return require('GameFSM.standstill').new('initial')
