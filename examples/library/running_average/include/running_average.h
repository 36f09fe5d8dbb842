/*
 * running_average.h — the average of the last N values added (a C++ class),
 * and the same for an arithmetic series from C.
 */
#ifndef RUNNING_AVERAGE_H
#define RUNNING_AVERAGE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The average of the last n terms of first, first + step, ... up to last. */
int running_average_of_last(int n, int first, int last, int step);

#ifdef __cplusplus
}

/* The average of the last window values added (at most 16). */
class RunningAverage {
public:
	explicit RunningAverage(int window);
	void add(int value);
	int value() const;
private:
	int values_[16];
	int window_;
	int count_;
	int next_;
};
#endif

#endif /* RUNNING_AVERAGE_H */
