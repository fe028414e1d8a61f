// a room that includes a later room: the check must fail
#include "workflows/wear/wear_run.h"
