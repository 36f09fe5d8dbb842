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

#endif /* EV3LX_HACK_INTERFACE_H */
