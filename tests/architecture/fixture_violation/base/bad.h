// a lower layer that includes a higher one: the check must fail
#include "workflows/run/run.h"
