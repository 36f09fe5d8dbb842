/*
 * kernel_cfg.h — the configuration of tests/ev3rt_link/not_yet_app.c, an app
 * with no objects of its own, as ev3cfg would write it: ev3api.h includes it.
 */
#ifndef TOPPERS_KERNEL_CFG_H
#define TOPPERS_KERNEL_CFG_H
#endif
