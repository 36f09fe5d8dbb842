/*
 * ev3rt_log.c — the warning EV3RT's calls log where they cannot return an error.
 */
#include "api_internal.h"

static const char *error_name(ER ercd)
{
	switch (ercd) {
	case E_OK:    return "E_OK";
	case E_ID:    return "E_ID";
	case E_PAR:   return "E_PAR";
	case E_OBJ:   return "E_OBJ";
	case E_MACV:  return "E_MACV";
	case E_TMOUT: return "E_TMOUT";
	case E_CTX:   return "E_CTX";
	case E_NOSPT: return "E_NOSPT";
	default:      return "error";
	}
}

void api_warn(const char *call, int arg, ER ercd)
{
	syslog(LOG_WARNING, "%s(%d): %s (%d)", call, arg, error_name(ercd), (int)ercd);
}
