/*
 * hack_interface.h — marks a module's interface.  A module (a hack file with
 * the driver it includes) is linked with a private namespace (mk/config.mk):
 * compiled -fvisibility=hidden and its hidden symbols localized, as a .ko's
 * are to the rest of the kernel.  What the rest of the firmware may name —
 * the hack's configuration fragment, which carries its service calls — is
 * declared HACK_INTERFACE in the hack's header.
 */
#ifndef EV3LX_HACK_INTERFACE_H
#define EV3LX_HACK_INTERFACE_H

#define HACK_INTERFACE __attribute__((visibility("default")))

/* The first extended service call function code of the library's modules: a
 * build setting (make EV3LX_FNCD_BASE=n), each module's range at a fixed
 * offset from it.  The default, 64, is clear of the codes EV3RT's own
 * drivers and system services define (1..42: target/ev3_gcc's .cfg files and
 * include/extsvc_fncode.h, ev3rt-git/ev3rt-hrp2), so the library's fragment
 * and EV3RT's configure together. */
#ifndef EV3LX_FNCD_BASE
#define EV3LX_FNCD_BASE 64
#endif

#endif /* EV3LX_HACK_INTERFACE_H */
