package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFit;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Predicate;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Models sent as zips, on a real server over raw sockets: an unsafe zip is refused by name at
 * registration, a version 1 client may not send one nor ask for a fit, and a version 1 viewer is
 * sent the agent without the model it could not read, while a version 2 viewer gets it whole.
 */
class ZipModelsTest {

    private static final String BODY = "{\"radius\":0.4,\"height\":1.6,\"maxSpeed\":2.0,\"gripper\":{\"part\":"
            + "\"hands\",\"reach\":0.6,\"minHeight\":0.0,\"maxHeight\":1.5},\"sight\":{\"range\":20.0,"
            + "\"fieldOfView\":3.0}}";

    private final MessageCodec codec = new MessageCodec();
    private WorldServer server;

    @BeforeEach
    void start() throws IOException {
        server = WorldServer.builder().port(0).seed(11).clock(ClockMode.REALTIME).waitFor(5).start();
    }

    @AfterEach
    void stop() {
        server.close();
    }

    private static String hello(int version, String role) {
        return "{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":" + version + ",\"role\":\"" + role
                + "\",\"client\":\"zip-test\"}";
    }

    private static String register(String name, ModelSpec model) {
        String fit = model.fit() == null ? "" : ",\"fit\":\"" + model.fit().wireName() + "\"";
        return "{\"type\":\"Register\",\"seq\":2,\"name\":\"" + name + "\",\"body\":" + BODY + ",\"model\":{\"format\":\""
                + model.format().wireName() + "\",\"data\":\"" + model.data() + "\"" + fit + "}}";
    }

    private static void send(Socket socket, String... lines) throws IOException {
        for (String line : lines) {
            socket.getOutputStream().write((line + "\n").getBytes(StandardCharsets.UTF_8));
        }
        socket.getOutputStream().flush();
    }

    private ServerMessage await(BufferedReader in, Predicate<ServerMessage> wanted) throws IOException {
        while (true) {
            String line = in.readLine();
            assertThat(line).as("the server's next line").isNotNull();
            ServerMessage message = codec.decodeServer(line);
            if (wanted.test(message)) {
                return message;
            }
        }
    }

    private static BufferedReader reader(Socket socket) throws IOException {
        socket.setSoTimeout(10_000);
        return new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
    }

    private ServerMessage answerToRegister(int version, ModelSpec model) throws IOException {
        try (Socket agent = new Socket("127.0.0.1", server.port())) {
            BufferedReader in = reader(agent);
            send(agent, hello(version, "agent"), register("Cat", model));
            return await(in, m -> m instanceof ErrorMessage || m instanceof RegisteredMessage);
        }
    }

    private static ModelSpec zip(Map<String, byte[]> files) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(out)) {
            for (Map.Entry<String, byte[]> file : files.entrySet()) {
                zip.putNextEntry(new ZipEntry(file.getKey()));
                zip.write(file.getValue());
            }
        }
        return new ModelSpec(ModelFormat.ZIP, null, Base64.getEncoder().encodeToString(out.toByteArray()));
    }

    private static ModelSpec goodZip() {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("Cat/scene.gltf", "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"name\":\"Cat\"}]}"
                .getBytes(StandardCharsets.UTF_8));
        files.put("Cat/scene.bin", new byte[16]);
        return ModelSpec.of(ModelFormat.ZIP, ModelArchive.pack(files));
    }

    @Test
    void aZipWithAPathLeavingTheArchiveIsRefusedByName() throws IOException {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("scene.gltf", "{}".getBytes(StandardCharsets.UTF_8));
        files.put("../../etc/cron.d/x", new byte[4]);

        assertThat(answerToRegister(2, zip(files))).isInstanceOfSatisfying(ErrorMessage.class, error -> {
            assertThat(error.code()).isEqualTo(ErrorCode.INVALID_VALUE);
            assertThat(error.seq()).isEqualTo(2);
            assertThat(error.text()).isEqualTo("model.data: the zip's entry '../../etc/cron.d/x' has a '..' segment,"
                    + " which would leave the archive");
        });
    }

    @Test
    void aZipBombIsRefused() throws IOException {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("scene.gltf", "{}".getBytes(StandardCharsets.UTF_8));
        files.put("zeros.bin", new byte[3 << 20]);

        assertThat(answerToRegister(2, zip(files))).isInstanceOfSatisfying(ErrorMessage.class,
                error -> assertThat(error.text()).contains("zip bomb"));
    }

    @Test
    void aSafeZipIsRegistered() throws IOException {
        assertThat(answerToRegister(2, goodZip())).isInstanceOf(RegisteredMessage.class);
    }

    @Test
    void aVersion1ClientMaySendNeitherAZipNorAFit() throws IOException {
        assertThat(answerToRegister(1, goodZip())).isInstanceOfSatisfying(ErrorMessage.class, error -> {
            assertThat(error.code()).isEqualTo(ErrorCode.INVALID_VALUE);
            assertThat(error.text()).isEqualTo("model.format 'zip' is protocol version 2; this client speaks version 1");
        });
        ModelSpec fitted = ModelSpec.of(ModelFormat.X3D, "<X3D/>".getBytes(StandardCharsets.UTF_8))
                .withFit(ModelFit.AUTHORED);
        assertThat(answerToRegister(1, fitted)).isInstanceOfSatisfying(ErrorMessage.class, error ->
                assertThat(error.text()).isEqualTo("model.fit is protocol version 2; this client speaks version 1"));
    }

    @Test
    void aVersion1ViewerGetsTheAgentWithoutTheZipAVersion2ViewerGetsItWhole() throws IOException {
        try (Socket old = new Socket("127.0.0.1", server.port());
             Socket current = new Socket("127.0.0.1", server.port());
             Socket agent = new Socket("127.0.0.1", server.port())) {
            BufferedReader oldIn = reader(old);
            BufferedReader currentIn = reader(current);
            send(old, hello(1, "viewer"));
            send(current, hello(2, "viewer"));
            await(oldIn, m -> m instanceof io.orchard.protocol.message.WorldSnapshotMessage);
            await(currentIn, m -> m instanceof io.orchard.protocol.message.WorldSnapshotMessage);
            ModelSpec model = goodZip().withFit(ModelFit.AUTHORED);
            send(agent, hello(2, "agent"), register("Cat", model));

            AgentAddedMessage seenByOld = (AgentAddedMessage) await(oldIn, m -> m instanceof AgentAddedMessage);
            AgentAddedMessage seenByCurrent = (AgentAddedMessage) await(currentIn, m -> m instanceof AgentAddedMessage);

            assertThat(seenByOld.agent().name()).isEqualTo("Cat");
            assertThat(seenByOld.agent().model()).isNull();
            assertThat(seenByCurrent.agent().model()).isEqualTo(model);
        }
    }
}
