// Must not compile: the neutral vehicle room (sortie_vehicle) does not see the VCI room's headers.
// tst_vehicle_layering_vci builds this and passes only on the "not found" error.
#include "Vehicle.h"
#include "VciMissionPlanner.h"
