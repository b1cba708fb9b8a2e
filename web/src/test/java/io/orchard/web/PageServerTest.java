package io.orchard.web;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.MessageCodec;
import io.orchard.server.WorldServer;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.net.http.WebSocketHandshakeException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The HTTP side and the WebSocket's own limits, without a browser: only the site's files, with
 * their content types and the Content-Security-Policy; the protocol over the WebSocket; frames over
 * the line limit, with a newline inside, or from another site's page refused.
 */
class PageServerTest {

    private static WorldServer server;
    private static int http;

    @BeforeAll
    static void start() throws IOException {
        server = WorldServer.builder().port(0).httpPort(0).seed(7).start();
        http = server.httpPort().orElseThrow();
    }

    @AfterAll
    static void stop() {
        server.close();
    }

    @Test
    void thePageAndItsScriptsComeWithTheirTypesAndThePolicy() throws IOException {
        Response page = get("/");
        assertThat(page.status()).isEqualTo(200);
        assertThat(page.header("content-type")).isEqualTo("text/html; charset=utf-8");
        assertThat(page.header("content-security-policy")).contains("default-src 'self'", "script-src 'self'",
                "object-src 'none'", "frame-ancestors 'none'").doesNotContain("unsafe");
        assertThat(page.header("x-content-type-options")).isEqualTo("nosniff");
        assertThat(page.body()).contains("<canvas id=\"world\"", "src=\"orchard.js\"");

        for (String script : List.of("/orchard.js", "/scene.js", "/agents.js", "/vendor/three/build/three.module.js",
                "/vendor/three/build/three.core.js", "/vendor/three/examples/jsm/loaders/GLTFLoader.js")) {
            Response response = get(script);
            assertThat(response.status()).as(script).isEqualTo(200);
            assertThat(response.header("content-type")).as(script).isEqualTo("text/javascript; charset=utf-8");
        }
        assertThat(get("/orchard.css").header("content-type")).isEqualTo("text/css; charset=utf-8");
        // The loaders import three.js by its path: a bare 'three' needs an inline import map.
        assertThat(get("/vendor/three/examples/jsm/loaders/GLTFLoader.js").body()).doesNotContain("from 'three'")
                .contains("from '../../../build/three.module.js'");
    }

    @Test
    void nothingButTheSitesOwnFilesIsServed() throws IOException {
        for (String path : List.of("/files.txt", "/vendor/", "/vendor/three/", "/../pom.xml", "/%2e%2e/%2e%2e/pom.xml",
                "/vendor/../../../../etc/passwd", "/io/orchard/web/WebViewer.class", "/index.html/",
                "//index.html", "/META-INF/MANIFEST.MF", "/nothing")) {
            Response response = get(path);
            assertThat(response.status()).as(path).isEqualTo(404);
            assertThat(response.body()).as(path).isEqualTo("not found\n");
        }
        Response post = request("POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 2\r\nConnection: close\r\n\r\nhi");
        assertThat(post.status()).isEqualTo(405);
        assertThat(post.header("allow")).isEqualTo("GET, HEAD");
        Response head = request("HEAD /orchard.js HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
        assertThat(head.status()).isEqualTo(200);
        assertThat(head.body()).isEmpty();
    }

    @Test
    void theWebSocketSpeaksTheProtocolAsAViewer() throws Exception {
        Lines lines = new Lines();
        WebSocket socket = open(lines, null);
        socket.sendText("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":2,\"role\":\"viewer\",\"client\":\"test\"}",
                true).join();
        assertThat(lines.next()).startsWith("{\"type\":\"Welcome\"").contains("\"role\":\"viewer\"");
        assertThat(lines.next()).startsWith("{\"type\":\"WorldSnapshot\"");
        socket.sendText("{\"type\":\"GameControl\",\"seq\":2,\"command\":\"start\"}", true).join();
        assertThat(lines.next()).startsWith("{\"type\":\"Error\"").contains("\"code\":\"forbidden\"");
        socket.sendClose(WebSocket.NORMAL_CLOSURE, "done").join();
    }

    @Test
    void aMessageOverTheLineLimitClosesTheWebSocket() throws Exception {
        Lines lines = new Lines();
        WebSocket socket = open(lines, null);
        socket.sendText("x".repeat(MessageCodec.MAX_LINE_BYTES + 1), true);
        assertThat(lines.closed.get(10, TimeUnit.SECONDS)).isEqualTo(1009);
    }

    @Test
    void aMessageOfTwoLinesClosesTheWebSocket() throws Exception {
        Lines lines = new Lines();
        WebSocket socket = open(lines, null);
        socket.sendText("{\"type\":\"KeepAlive\",\"seq\":1}\n{\"type\":\"KeepAlive\",\"seq\":2}", true);
        assertThat(lines.closed.get(10, TimeUnit.SECONDS)).isEqualTo(1007);
    }

    @Test
    void anotherSitesPageCannotOpenTheWebSocket() {
        assertThatThrownBy(() -> open(new Lines(), "http://elsewhere.example"))
                .isInstanceOf(CompletionException.class)
                .hasCauseInstanceOf(WebSocketHandshakeException.class);
    }

    @Test
    void originsAreComparedWithTheHostAskedFor() {
        assertThat(SameOrigin.allowed(null, "localhost:8080")).isTrue();
        assertThat(SameOrigin.allowed("http://localhost:8080", "localhost:8080")).isTrue();
        assertThat(SameOrigin.allowed("http://localhost:8081", "localhost:8080")).isFalse();
        assertThat(SameOrigin.allowed("http://evil.localhost:8080", "localhost:8080")).isFalse();
        assertThat(SameOrigin.allowed("null", "localhost:8080")).isFalse();
        assertThat(SameOrigin.allowed("http://localhost:8080", null)).isFalse();
    }

    private static WebSocket open(Lines lines, String origin) {
        WebSocket.Builder builder = HttpClient.newHttpClient().newWebSocketBuilder();
        if (origin != null) {
            builder.header("Origin", origin);
        }
        return builder.buildAsync(URI.create("ws://127.0.0.1:" + http + "/socket"), lines).join();
    }

    /** The lines the WebSocket receives, and the close code it gets. */
    private static final class Lines implements WebSocket.Listener {

        final BlockingQueue<String> received = new LinkedBlockingQueue<>();
        final CompletableFuture<Integer> closed = new CompletableFuture<>();
        private final StringBuilder parts = new StringBuilder();

        @Override
        public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
            parts.append(data);
            if (last) {
                received.add(parts.toString());
                parts.setLength(0);
            }
            webSocket.request(1);
            return null;
        }

        @Override
        public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
            closed.complete(statusCode);
            return null;
        }

        @Override
        public void onError(WebSocket webSocket, Throwable error) {
            closed.completeExceptionally(error);
        }

        String next() throws InterruptedException {
            String line = received.poll(10, TimeUnit.SECONDS);
            assertThat(line).as("a line from the server within 10 s").isNotNull();
            return line;
        }
    }

    private record Response(int status, String headers, String body) {

        String header(String name) {
            return headers.lines().filter(line -> line.toLowerCase(java.util.Locale.ROOT).startsWith(name + ":"))
                    .map(line -> line.substring(line.indexOf(':') + 1).strip()).findFirst().orElse(null);
        }
    }

    private static Response get(String path) throws IOException {
        return request("GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + http + "\r\nConnection: close\r\n\r\n");
    }

    /** A request sent as written, so that no client tidies its path first. */
    private static Response request(String raw) throws IOException {
        try (Socket socket = new Socket("127.0.0.1", http)) {
            OutputStream out = socket.getOutputStream();
            out.write(raw.getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
            InputStream in = socket.getInputStream();
            String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            int end = text.indexOf("\r\n\r\n");
            String head = text.substring(0, end);
            return new Response(Integer.parseInt(head.split(" ")[1]), head, text.substring(end + 4));
        }
    }
}
