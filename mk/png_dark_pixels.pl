#!/usr/bin/perl
# png_dark_pixels.pl FILE.png — prints the number of black pixels of an
# ev3sim --lcd PNG (178 x 128, 8-bit grey, not interlaced, each pixel 0 or
# 255), decoding it with perl's core zlib and the PNG row filters (PNG
# specification, sections 9-11); exits 1 with a reason for anything else.
use strict;
use warnings;
use Compress::Zlib;

my $path = shift or die "usage: png_dark_pixels.pl FILE.png\n";
open(my $fh, '<:raw', $path) or do { print "cannot open $path\n"; exit 1 };
local $/;
my $png = <$fh>;
close($fh);
sub fail { print "$_[0]\n"; exit 1 }
fail("not a PNG") unless substr($png, 0, 8) eq "\x89PNG\r\n\x1a\n";
my ($pos, $idat, $w, $h) = (8, '', 0, 0);
while ($pos + 8 <= length($png)) {
	my ($len, $type) = unpack('N a4', substr($png, $pos, 8));
	my $data = substr($png, $pos + 8, $len);
	fail("bad CRC in $type") unless crc32($type . $data) == unpack('N', substr($png, $pos + 8 + $len, 4));
	if ($type eq 'IHDR') {
		my ($depth, $colour, $interlace);
		($w, $h, $depth, $colour, undef, undef, $interlace) = unpack('N N C C C C C', $data);
		fail("not 178 x 128 8-bit grey") unless $w == 178 && $h == 128 && $depth == 8 && $colour == 0 && !$interlace;
	}
	$idat .= $data if $type eq 'IDAT';
	last if $type eq 'IEND';
	$pos += 12 + $len;
}
my $raw = uncompress($idat);
fail("IDAT does not inflate") unless defined $raw && length($raw) == $h * ($w + 1);
my ($dark, @prev) = (0, (0) x $w);
for my $y (0 .. $h - 1) {
	my $filter = ord(substr($raw, $y * ($w + 1), 1));
	my @row = unpack('C*', substr($raw, $y * ($w + 1) + 1, $w));
	for my $x (0 .. $w - 1) {
		my ($a, $b, $c) = ($x ? $row[$x - 1] : 0, $prev[$x], $x ? $prev[$x - 1] : 0);
		my $p = $a + $b - $c;
		my ($pa, $pb, $pc) = (abs($p - $a), abs($p - $b), abs($p - $c));
		my $pred = $filter == 0 ? 0 : $filter == 1 ? $a : $filter == 2 ? $b : $filter == 3 ? int(($a + $b) / 2)
			: ($pa <= $pb && $pa <= $pc) ? $a : $pb <= $pc ? $b : $c;
		fail("unknown filter $filter") if $filter > 4;
		$row[$x] = ($row[$x] + $pred) & 0xff;
		fail("pixel ($x, $y) is $row[$x], neither black nor white") unless $row[$x] == 0 || $row[$x] == 255;
		$dark++ if $row[$x] == 0;
	}
	@prev = @row;
}
print "$dark\n";
