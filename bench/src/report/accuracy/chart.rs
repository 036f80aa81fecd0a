//! The time-against-error chart: one panel per scene, one mark per setting, the default highlighted.
//!
//! Drawn with `plotters` into memory; text uses DejaVu Sans (Bitstream Vera licence) compiled in from the `dejavu`
//! crate, so no system font library is involved.

use plotters::prelude::*;
use plotters::style::{FontStyle, register_font};

/// One mark: a setting's time relative to the default and its PSNR.
pub struct Mark<'a> {
    /// The setting's name.
    pub label: &'a str,
    /// Time relative to the default setting.
    pub relative_time: f64,
    /// PSNR in dB (infinite values are drawn at the top).
    pub psnr: f64,
    /// The default setting.
    pub highlighted: bool,
}

/// Highest PSNR drawn; an exact match is drawn here.
const PSNR_CEILING: f64 = 60.0;

/// Draws the panels (scene name and marks) as a `width x height` image of `0x00RRGGBB` pixels.
///
/// # Errors
/// A message when the font cannot be registered or plotters fails.
pub fn draw(panels: &[(&str, Vec<Mark<'_>>)], width: u32, height: u32) -> Result<Vec<u32>, String> {
    register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "cannot load the chart font")?;
    let mut rgb = vec![0u8; width as usize * height as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root
            .titled("Time against accuracy of each quality setting (one knob changed at a time)", ("sans-serif", 20))
            .map_err(|e| e.to_string())?;
        let columns = 2usize;
        let rows = panels.len().div_ceil(columns);
        for (area, (name, marks)) in root.split_evenly((rows, columns)).iter().zip(panels) {
            draw_panel(area, name, marks)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(rgb.chunks_exact(3).map(|p| (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2])).collect())
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    name: &str,
    marks: &[Mark<'_>],
) -> Result<(), String> {
    let psnr = |m: &Mark<'_>| m.psnr.min(PSNR_CEILING);
    let (t_lo, t_hi) =
        marks.iter().fold((f64::MAX, f64::MIN), |(a, b), m| (a.min(m.relative_time), b.max(m.relative_time)));
    let (p_lo, p_hi) = marks.iter().fold((f64::MAX, f64::MIN), |(a, b), m| (a.min(psnr(m)), b.max(psnr(m))));
    let mut chart = ChartBuilder::on(area)
        .caption(name, ("sans-serif", 17))
        .margin(12)
        .x_label_area_size(38)
        .y_label_area_size(48)
        .build_cartesian_2d((t_lo * 0.7..t_hi * 1.6).log_scale(), (p_lo - 2.0).floor()..(p_hi + 2.0).ceil())
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("frame time relative to the default (log scale)")
        .y_desc("PSNR against the reference (dB)")
        .axis_desc_style(("sans-serif", 13))
        .label_style(("sans-serif", 12))
        .x_labels(6)
        .x_label_formatter(&|v| if *v < 1.0 { format!("{v:.2}x") } else { format!("{v:.1}x") })
        .draw()
        .map_err(|e| e.to_string())?;
    let accent = RGBColor(214, 39, 40);
    let plain = RGBColor(31, 119, 180);
    chart
        .draw_series(marks.iter().map(|m| {
            let style = if m.highlighted { accent.filled() } else { plain.filled() };
            Circle::new((m.relative_time, psnr(m)), if m.highlighted { 6 } else { 4 }, style)
        }))
        .map_err(|e| e.to_string())?;
    // Labels beside their marks, moved down where they would overlap an earlier one.
    let base = area.get_base_pixel();
    let mut order: Vec<(usize, (i32, i32))> =
        marks.iter().enumerate().map(|(i, m)| (i, chart.backend_coord(&(m.relative_time, psnr(m))))).collect();
    order.sort_by_key(|&(_, (x, y))| (y, x));
    let mut placed: Vec<(i32, i32, i32)> = Vec::new(); // left, top, right
    for (i, (x, y)) in order {
        let m = &marks[i];
        let width = 7 * m.label.chars().count() as i32;
        let (left, mut top) = (x + 8, y - 8);
        while placed.iter().any(|&(l, t, r)| left < r && l < left + width && (top - t).abs() < 14) {
            top += 14;
        }
        placed.push((left, top, left + width));
        let color = if m.highlighted { accent } else { RGBColor(60, 60, 60) };
        let style = ("sans-serif", 12).into_font().color(&color);
        area.draw(&Text::new(m.label.to_string(), (left - base.0, top - base.1), style)).map_err(|e| e.to_string())?;
    }
    Ok(())
}
