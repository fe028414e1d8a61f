// fine on its own
#include "base/bad.h"
