/*
 * ev3api_cfg.h — the API's own configuration, as the table an application's
 * configuration INCLUDEs (EV3LX_INCLUDE_TABLE(ev3api_cfg) in cfg/app_common.cfg).
 * EV3RT's ev3api.h includes a header of this name with the API's object IDs;
 * ev3lx's API objects are created by its table, so apps see none of them.
 */
#ifndef EV3API_CFG_H
#define EV3API_CFG_H

#ifdef __cplusplus
extern "C" {
#endif

#ifndef TOPPERS_MACRO_ONLY
struct rtos_cfg;

/* linux_compat, the drivers' service calls, the API's button task and the
 * memory regions the API reads (api/src/config.c). */
extern const struct rtos_cfg ev3api_cfg;
#endif

#ifdef __cplusplus
}
#endif

#endif /* EV3API_CFG_H */
