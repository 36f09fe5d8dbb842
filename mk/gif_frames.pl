#!/usr/bin/perl
# gif_frames.pl FILE.gif — decodes an animated GIF with nothing but perl
# (its blocks and its LZW, GIF89a specification) and prints
# "<frames> <total delay in 1/100 s> <dark pixels of the last frame>", the
# dark colour being index 1; exits 1 with a message if the file is not a
# well-formed GIF.
use strict;
use warnings;

my $path = shift or die "usage: gif_frames.pl FILE.gif\n";
open(my $fh, '<:raw', $path) or die "$path: $!\n";
local $/;
my $d = <$fh>;
close($fh);
my $p = 0;
sub take { my $n = shift; die "truncated\n" if $p + $n > length($d); my $s = substr($d, $p, $n); $p += $n; return $s; }
sub sub_blocks { my $s = ''; while (1) { my $n = ord(take(1)); last if $n == 0; $s .= take($n); } return $s; }

die "not a GIF\n" unless take(6) =~ /^GIF8[79]a$/;
my ($w, $h, $packed) = unpack('vvC', take(7));
take(3 * (1 << (($packed & 7) + 1))) if $packed & 0x80;
my ($frames, $delay, $dark) = (0, 0, 0);
while (1) {
	my $b = ord(take(1));
	if ($b == 0x3B) {
		last;
	} elsif ($b == 0x21) {
		my $label = ord(take(1));
		my $data = sub_blocks();
		$delay += unpack('v', substr($data, 1, 2)) if $label == 0xF9 && length($data) >= 3;
	} elsif ($b == 0x2C) {
		my ($l, $t, $iw, $ih, $ip) = unpack('vvvvC', take(9));
		take(3 * (1 << (($ip & 7) + 1))) if $ip & 0x80;
		my $min = ord(take(1));
		my $bits = unpack('b*', sub_blocks());
		my ($clear, $size, $pos, @dict, @out, $prev) = (1 << $min, $min + 1, 0);
		my $reset = sub { @dict = map { [$_] } 0 .. (1 << $min) + 1; $size = $min + 1; undef $prev; };
		$reset->();
		while ($pos + $size <= length($bits)) {
			my $code = oct('0b' . reverse(substr($bits, $pos, $size)));
			$pos += $size;
			if ($code == $clear) { $reset->(); next; }
			last if $code == $clear + 1;
			my $entry;
			if ($code < @dict) { $entry = $dict[$code]; }
			elsif (defined $prev && $code == @dict) { $entry = [@$prev, $prev->[0]]; }
			else { die "bad LZW code\n"; }
			push @out, @$entry;
			push @dict, [@$prev, $entry->[0]] if defined $prev && @dict < 4096;
			$prev = $entry;
			$size++ if @dict == (1 << $size) && $size < 12;
		}
		die "frame of " . scalar(@out) . " pixels, not " . ($iw * $ih) . "\n" unless @out == $iw * $ih;
		$frames++;
		$dark = grep { $_ == 1 } @out;
	} else {
		die sprintf("unknown block 0x%02x\n", $b);
	}
}
print "$frames $delay $dark\n";
