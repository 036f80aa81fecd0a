//! How large an image frame is: the pixels of the cells it covers, capped so that a large window keeps its frame
//! rate, and smaller still while it moves over a slow link.

use super::GraphicsProtocol;

/// The most pixels of an image frame: past it the image is rendered smaller and the terminal scales it up
/// (kitty, iTerm2) or shows it smaller (Sixel), so that a large window keeps its frame rate.
pub const MAX_IMAGE_PIXELS: usize = 640 * 480;
/// The fewest pixels of a moving image on a slow link (160x120 in a 4:3 window).
pub const MIN_IMAGE_PIXELS: usize = MAX_IMAGE_PIXELS / 16;
/// Cell height over width when neither `--cell-aspect` nor the terminal says: most monospace fonts.
pub const DEFAULT_CELL_ASPECT: f32 = 2.0;
/// The cell width in pixels assumed when the terminal does not give its size in pixels; the height is this times
/// the cell aspect.
pub const ASSUMED_CELL_WIDTH: f32 = 8.0;

/// The most pixels of a moving image when the link carries `link_pixels` in the time a frame may take (the viewer
/// measures it): the largest of [`MAX_IMAGE_PIXELS`] halved 0 to 4 times that fits, and at
/// least [`MIN_IMAGE_PIXELS`]. In steps, so that the picture's sharpness does not flicker with each frame's bytes;
/// only for protocols the terminal scales ([`GraphicsProtocol::scaled_by_terminal`]): a smaller Sixel image would
/// show a smaller picture, so Sixel keeps its size and only its frame rate falls.
pub fn moving_image_cap(protocol: GraphicsProtocol, link_pixels: Option<usize>) -> usize {
    let Some(link) = link_pixels.filter(|_| protocol.scaled_by_terminal()) else { return MAX_IMAGE_PIXELS };
    let mut cap = MAX_IMAGE_PIXELS;
    while cap > link && cap > MIN_IMAGE_PIXELS {
        cap /= 2;
    }
    cap
}

/// The pixel size of an image frame for a terminal of `size` cells, `size_in_pixels` when it says: the pixels of
/// the cells the image covers ([`GraphicsProtocol::image_rows`]), cells of [`ASSUMED_CELL_WIDTH`] by
/// `cell_aspect` times that when it does not say; scaled down to at most `max_pixels` (at most
/// [`MAX_IMAGE_PIXELS`], or less on a slow link: [`moving_image_cap`]); the height a whole number of
/// [`GraphicsProtocol::row_multiple`]; at least one row of them.
pub fn image_size(
    protocol: GraphicsProtocol,
    (cols, rows): (u16, u16),
    size_in_pixels: Option<(u16, u16)>,
    cell_aspect: f32,
    max_pixels: usize,
) -> (usize, usize) {
    let (cell_width, cell_height) = match size_in_pixels {
        Some((width, height)) => {
            (f32::from(width) / f32::from(cols.max(1)), f32::from(height) / f32::from(rows.max(1)))
        }
        None => (ASSUMED_CELL_WIDTH, ASSUMED_CELL_WIDTH * cell_aspect),
    };
    let mut width = f32::from(cols) * cell_width;
    let mut height = f32::from(protocol.image_rows(rows)) * cell_height;
    let area = width * height;
    if area > max_pixels as f32 {
        let scale = (max_pixels as f32 / area).sqrt();
        (width, height) = (width * scale, height * scale);
    }
    let multiple = protocol.row_multiple();
    let height = ((height as usize) / multiple * multiple).max(multiple);
    ((width as usize).max(1), height)
}
