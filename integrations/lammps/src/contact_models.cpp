/* placeholder */
#include "contact_models.h"
