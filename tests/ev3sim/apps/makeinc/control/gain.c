/*
 * gain.c — found through Makefile.inc's SRCDIRS; scales by COPTS's
 * GAIN_PERCENT.
 */
#include "app.h"

int gain_apply(int value)
{
	return value * GAIN_PERCENT / 100;
}
