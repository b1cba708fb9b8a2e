package io.orchard.examples.tournament;

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
 * box from the first to the third quartile with the median across it, the whiskers reaching one
 * and a half box heights beyond it or to the agent's best and worst game if those are nearer, any
 * game further out a cross — each labelled with its mean and standard deviation. Drawn with
 * XChart in Java2D: it needs no display, but AWT needs fonts (fontconfig and a font such as DejaVu
 * on Linux).
 */
final class FruitChart {

    static final String FILE = "chart.png";
    static final int WIDTH = 960;
    static final int HEIGHT = 540;

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
        for (Summary summary : summaries) {
            int[] fruit = results.stream().filter(r -> r.agent().equals(summary.agent())).mapToInt(Result::fruit)
                    .toArray();
            chart.addSeries(String.format(Locale.ROOT, "%s %.1f ± %.1f", summary.agent(), summary.meanFruit(),
                    summary.sdFruit()), fruit);
        }
        Path file = dir.resolve(FILE);
        Files.deleteIfExists(file);
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
        return file;
    }
}
