/*
 * syssvc/serial.h — TOPPERS's serial interface: the EV3's serial ports
 * (target_serial.h's SIO_PORT_*) as byte streams (public source:
 * ev3rt-git/ev3rt-hrp2, syssvc/serial.h).  The ports are the ones
 * ev3_serial_open_file gives as files: SIO_PORT_UART is EV3_SERIAL_UART,
 * SIO_PORT_BT EV3_SERIAL_BT, SIO_PORT_USB_CDC EV3_SERIAL_USB_CDC; the
 * platform opens them at boot, as EV3RT does.  Task context only.
 */
#ifndef TOPPERS_SERIAL_H
#define TOPPERS_SERIAL_H

#include "kernel.h"
#include "target_serial.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A port's state (serial_ref_por). */
typedef struct {
	uint_t reacnt;   /* bytes waiting to be read */
	uint_t wricnt;   /* bytes waiting to be sent */
} T_SERIAL_RPOR;

/* Port modes (serial_ctl_por). */
#define IOCTL_NULL   0U       /* none */
#define IOCTL_ECHO   0x0001U  /* echo what is received */
#define IOCTL_CRLF   0x0010U  /* send CR before LF */
#define IOCTL_FCSND  0x0100U  /* flow control on sending */
#define IOCTL_FCANY  0x0200U  /* any character resumes sending */
#define IOCTL_FCRCV  0x0400U  /* flow control on receiving */

/* E_OK if portid is a port the platform provides (it is open from boot);
 * E_ID if there is no such port, E_NOSPT for a port ev3lx does not provide. */
ER serial_opn_por(ID portid) throw();

/* Checks portid as serial_opn_por does; the port stays open (the platform owns it). */
ER serial_cls_por(ID portid) throw();

/* Reads exactly len bytes into buf, waiting for them; the count, or E_ID,
 * E_NOSPT, E_PAR (len), E_MACV (buf), E_CTX, E_OBJ (the far end closed). */
ER_UINT serial_rea_dat(ID portid, char *buf, uint_t len) throw();

/* Writes len bytes of buf, waiting while the port is full; the count
 * (IOCTL_CRLF's added CRs not counted), or the errors of serial_rea_dat. */
ER_UINT serial_wri_dat(ID portid, const char *buf, uint_t len) throw();

/* Sets the port's modes: IOCTL_CRLF and IOCTL_ECHO are honoured, flow
 * control is accepted (the simulated links never overrun); E_PAR for
 * other bits. */
ER serial_ctl_por(ID portid, uint_t ioctl) throw();

/* The port's state: nothing is ever left waiting in ev3lx's buffers. */
ER serial_ref_por(ID portid, T_SERIAL_RPOR *pk_rpor) throw();

#ifdef __cplusplus
}
#endif

#endif /* TOPPERS_SERIAL_H */
