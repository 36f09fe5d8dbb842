/*
 * trace.h — signal traces of the simulation.  Host only.
 *
 * Models declare signals (GPIO pins and interrupt lines are declared by the
 * core) and set their values; every change is stamped with the virtual time.
 * Outputs, each optional:
 *   - VCD (Value Change Dump, timescale 1 ns) that GTKWave and PulseView open:
 *     all signals, 1-bit ones as wires (pins floating show 'z'), wider ones
 *     as vectors, real ones as reals;
 *   - CSV "time_ns,signal,value" of the numeric signals (width > 1 or real);
 *   - a register-access log, one line per CPU access, filtered by region.
 * Same inputs and seed give byte-identical files.
 */
#ifndef HOST_SIM_TRACE_H
#define HOST_SIM_TRACE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

struct hs_signal;

/* Declares (or finds, if scope/name exists) a signal of width bits (1..64).
 * scope groups signals in the VCD ("gpio", "irq", "motorA"); names use
 * [A-Za-z0-9_.]. Its value is unknown ('x') until first set. */
struct hs_signal *hs_trace_signal(const char *scope, const char *name, unsigned width);
/* Declares a real-valued signal (angles, voltages). */
struct hs_signal *hs_trace_signal_real(const char *scope, const char *name);
/* Finds a declared signal, or NULL. */
struct hs_signal *hs_trace_find(const char *scope, const char *name);

/* Sets the value now (recorded only if it changes). */
void hs_trace_set(struct hs_signal *s, uint64_t value);
/* Sets a 1-bit signal to high impedance ('z'). */
void hs_trace_set_z(struct hs_signal *s);
void hs_trace_set_real(struct hs_signal *s, double value);
/* hs_trace_set_real of a, then of b, at one instant (both real-valued signals). */
void hs_trace_set_real_pair(struct hs_signal *a, double va, struct hs_signal *b, double vb);
/* A 1-ns pulse on a 1-bit signal (a latched event such as an interrupt request). */
void hs_trace_pulse(struct hs_signal *s);

/* Reading back, for assertions. */
uint64_t hs_signal_value(const struct hs_signal *s);
double hs_signal_real(const struct hs_signal *s);
bool hs_signal_is_z(const struct hs_signal *s);
/* Number of value changes since declaration, and the time of the last one. */
uint64_t hs_signal_changes(const struct hs_signal *s);
uint64_t hs_signal_last_change(const struct hs_signal *s);

/* Starts writing a VCD / CSV file (written completely by hs_trace_close).
 * Return 0, or -1 with errno. */
int hs_trace_open_vcd(const char *path);
int hs_trace_open_csv(const char *path);
/* Flushes and closes the files (also done by hs_board_shutdown); 0, or -1 if
 * one of them could not be written completely (a full disk). */
int hs_trace_close(void);

/* Logs register accesses of the regions named in filter (comma-separated,
 * "*" for all; NULL stops logging) to out, or to rtos_host_trace (source
 * "mmio") if out is NULL.  Line: "<ns> <R|W><width> <REGION>.<REG> @0x<phys> = 0x<value>". */
void hs_trace_reglog(const char *filter, FILE *out);

#endif /* HOST_SIM_TRACE_H */
