//! A CSV record with `#` comment lines after the first line (as the records
//! shipped with pySLAMMER have) was refused: "not a number" on the comment.
//! Comments are now skipped wherever they are, and the samples are those of
//! the same file without them.

use rocking::{AccelerationUnit, CsvOptions, Record, RecordFormat};

#[test]
fn comment_lines_anywhere_are_skipped() {
    let options = CsvOptions {
        units: AccelerationUnit::MetersPerSecond2,
        dt: None,
    };
    let plain = "time,acc\n0.0,0.5\n0.01,-0.25\n0.02,0.125\n";
    let commented = "# pySLAMMER-style record\ntime,acc\n0.0,0.5\n# a comment between samples\n0.01,-0.25\n  # indented\n0.02,0.125\n# end\n";
    let a = Record::parse(plain, Some(RecordFormat::Csv), &options, 9.81).unwrap_or_else(|e| panic!("{e}"));
    let b = Record::parse(commented, Some(RecordFormat::Csv), &options, 9.81).unwrap_or_else(|e| panic!("{e}"));
    // Same text minus the comments: the same samples, bit for bit.
    assert_eq!(a, b);
    assert_eq!(b.values(), &[0.5, -0.25, 0.125]);
    assert_eq!(Record::guess_format(commented).ok(), Some(RecordFormat::Csv));
}
