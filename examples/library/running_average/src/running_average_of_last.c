/*
 * running_average_of_last.c — the library's C function.
 */
#include "running_average.h"

int running_average_of_last(int n, int first, int last, int step)
{
	int sum = 0, count = 0;

	for (int v = last; v >= first && count < n; v -= step, count++)
		sum += v;
	return count > 0 ? sum / count : 0;
}
