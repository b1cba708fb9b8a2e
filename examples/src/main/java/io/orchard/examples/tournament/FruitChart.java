package io.orchard.examples.tournament;

import java.awt.Color;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.BoxChart;
import org.knowm.xchart.BoxChartBuilder;
import org.knowm.xchart.style.BoxStyler;

/**
 * The tournament's chart, chart.png: one box per agent of the fruit it collected per game — the
 * box from the first to the third quartile with the median across it, the whiskers out to the
 * furthest games within one and a half box heights, any game beyond them a cross — each labelled
 * with its mean and standard deviation. Drawn with XChart in Java2D; it needs no
 * display, but AWT needs fonts (fontconfig and a font such as DejaVu on Linux).
 */
final class FruitChart {

    static final String FILE = "chart.png";
    static final int WIDTH = 960;
    static final int HEIGHT = 540;

    /** Light fills, one per agent, so that the median line and the whiskers stay legible over them. */
    private static final Color[] FILLS = {new Color(0x9ecae1), new Color(0xfdae6b), new Color(0xa1d99b),
        new Color(0xfc9fb5), new Color(0xbcbddc), new Color(0xfee391), new Color(0xc7e9c0), new Color(0xd9d9d9)};

    private FruitChart() {}

    static Path write(List<Result> results, List<Summary> summaries, String title, Path dir) throws IOException {
        if (System.getProperty("java.awt.headless") == null) {
            // Java2D only: no window, so no display is needed, and none is looked for.
            System.setProperty("java.awt.headless", "true");
        }
        BoxChart chart = new BoxChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle("agent (mean ± standard deviation)").yAxisTitle("fruit per game").build();
        BoxStyler style = chart.getStyler();
        style.setLegendVisible(false);
        style.setYAxisMin(0.0);
        style.setPlotGridVerticalLinesVisible(false);
        for (int i = 0; i < summaries.size(); i++) {
            Summary summary = summaries.get(i);
            int[] fruit = results.stream().filter(r -> r.agent().equals(summary.agent())).mapToInt(Result::fruit)
                    .toArray();
            chart.addSeries(String.format(Locale.ROOT, "%s %.1f ± %.1f", summary.agent(), summary.meanFruit(),
                    summary.sdFruit()), fruit).setFillColor(FILLS[i % FILLS.length]);
        }
        Path file = dir.resolve(FILE);
        Files.deleteIfExists(file);
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
        return file;
    }
}
