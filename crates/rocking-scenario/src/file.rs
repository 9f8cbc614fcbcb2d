//! Reading a file the user named, bounded by what it holds: a device or a
//! pipe (`/dev/zero`, a link to one) is refused before a byte is read, and a
//! file is read no further than a limit of its kind, even if it grows while
//! it is read. A read never allocates more than the file holds.

use std::io::{Error, ErrorKind, Read};
use std::path::Path;

/// Largest scenario, sweep, study or manifest file read (bytes): a thousand
/// times the largest the project ships.
pub const MAX_INPUT_BYTES: u64 = 16 << 20;

/// The bytes of the regular file `path`, at most `limit` of them: an error of
/// kind `InvalidInput` ("not a regular file", "N bytes, more than the …") for
/// anything else.
pub fn read_bytes(path: &Path, limit: u64) -> std::io::Result<Vec<u8>> {
    let too_large = |size: String| {
        Error::new(
            ErrorKind::InvalidInput,
            format!("{size}more than the {} a file of its kind may have", size_text(limit)),
        )
    };
    let file = std::fs::File::open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(Error::new(ErrorKind::InvalidInput, "not a regular file"));
    }
    if meta.len() > limit {
        return Err(too_large(format!("{} bytes, ", meta.len())));
    }
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    // `take` bounds the read even if the file grows while it is read.
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(too_large(String::new()));
    }
    Ok(bytes)
}

/// The text of the regular file `path` ([`read_bytes`]); an error of kind
/// `InvalidData` if it is not UTF-8.
pub fn read_text(path: &Path, limit: u64) -> std::io::Result<String> {
    String::from_utf8(read_bytes(path, limit)?).map_err(|_| Error::new(ErrorKind::InvalidData, "not UTF-8 text"))
}

/// `limit` in MiB, kiB or bytes, for messages.
fn size_text(limit: u64) -> String {
    match limit {
        0..1024 => format!("{limit} bytes"),
        1024..1_048_576 => format!("{} kiB", limit >> 10),
        _ => format!("{} MiB", limit >> 20),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_read_whole_up_to_its_limit() -> std::io::Result<()> {
        let dir = tempfile::tempdir()?;
        let path = dir.path().join("a.toml");
        std::fs::write(&path, "x = 1\n")?;
        assert_eq!(read_text(&path, 6)?, "x = 1\n");
        let e = read_text(&path, 5).err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("6 bytes, more than the 5 bytes a file of its kind may have"));
        std::fs::write(&path, [0xff, 0xfe])?;
        assert_eq!(read_text(&path, 6).err().map(|e| e.kind()), Some(ErrorKind::InvalidData));
        Ok(())
    }

    #[cfg(unix)]
    #[test]
    fn a_device_is_refused_before_it_is_read() {
        // /dev/zero never ends: read whole, it would fill the memory.
        let e = read_bytes(Path::new("/dev/zero"), MAX_INPUT_BYTES).err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("not a regular file"));
    }
}
