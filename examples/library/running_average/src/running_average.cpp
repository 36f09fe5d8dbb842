/*
 * running_average.cpp — RunningAverage: a ring of the last window values.
 */
#include "running_average.h"

RunningAverage::RunningAverage(int window)
	: values_(), window_(window < 1 ? 1 : window > 16 ? 16 : window), count_(0), next_(0)
{
}

void RunningAverage::add(int value)
{
	values_[next_] = value;
	next_ = (next_ + 1) % window_;
	if (count_ < window_)
		count_++;
}

int RunningAverage::value() const
{
	int sum = 0;

	for (int i = 0; i < count_; i++)
		sum += values_[i];
	return count_ > 0 ? sum / count_ : 0;
}
