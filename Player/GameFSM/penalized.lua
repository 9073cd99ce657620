-- Penalized: stand still until released (the robot is taken off and put back on the field: it
-- localizes afresh); then the search starts afresh (GameFSM.standstill).
return require('GameFSM.standstill').new('penalized')
